#!/usr/bin/env bash
# A real one-node Slurm cluster in a folder, for tests (Debian's slurmctld, slurmd, slurm-client; no
# munge daemon, nothing under /etc touched). Recipe: docs/cluster.md, "Testing".
#
#   scripts/slurm-test-cluster.sh start DIR   start the cluster; prints `export SLURM_CONF=DIR/etc/slurm.conf`
#   scripts/slurm-test-cluster.sh stop DIR    stop it (waits for running job steps first)
#   scripts/slurm-test-cluster.sh install     install the Debian packages (as root)
#
# Exit status 77 from start when the Slurm programs are missing (ctest reports the test skipped).
set -euo pipefail

mode=${1:-}
base=${2:-}

case "$mode" in
  install)
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends slurmctld slurmd slurm-client
    ;;
  start)
    [ -n "$base" ] || { echo "usage: $0 start DIR" >&2; exit 2; }
    for program in slurmctld slurmd sbatch squeue sinfo scontrol; do
      command -v "$program" >/dev/null || { echo "slurm-test-cluster: $program not installed (scripts/setup.sh deps)" >&2; exit 77; }
    done
    [ "$(id -u)" -eq 0 ] || { echo "slurm-test-cluster: needs root (SlurmUser=root)" >&2; exit 77; }
    mkdir -p "$base/etc" "$base/spool" "$base/state" "$base/log"
    base=$(cd "$base" && pwd)
    # Two free ports: bind to port 0 and read what the kernel gave.
    read -r ctld_port slurmd_port < <(/usr/bin/python3 -c '
import socket
s = [socket.socket() for _ in range(2)]
for x in s: x.bind(("127.0.0.1", 0))
print(*[x.getsockname()[1] for x in s])')
    cpus=$(nproc)
    cat >"$base/etc/slurm.conf" <<CONF
ClusterName=echoplan-test
SlurmctldHost=localhost
SlurmUser=root
SlurmdUser=root
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
AuthType=auth/none
CredType=cred/none
StateSaveLocation=$base/state
SlurmdSpoolDir=$base/spool
SlurmctldPidFile=$base/slurmctld.pid
SlurmdPidFile=$base/slurmd.pid
SlurmctldLogFile=$base/log/slurmctld.log
SlurmdLogFile=$base/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
MpiDefault=none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
ReturnToService=2
InactiveLimit=0
MinJobAge=300
KillWait=5
Waittime=0
MailProg=/bin/true
SchedulerParameters=batch_sched_delay=0,sched_interval=1
NodeName=localhost NodeAddr=127.0.0.1 CPUs=$cpus RealMemory=1000 State=UNKNOWN
PartitionName=debug Nodes=localhost Default=YES MaxTime=INFINITE State=UP
CONF
    export SLURM_CONF=$base/etc/slurm.conf
    slurmctld -D -i >"$base/log/slurmctld.out" 2>&1 &
    echo $! >"$base/slurmctld.child"
    slurmd -D -N localhost >"$base/log/slurmd.out" 2>&1 &
    echo $! >"$base/slurmd.child"
    for _ in $(seq 1 300); do
      [ "$(sinfo -h -o %T 2>/dev/null)" = idle ] && { echo "export SLURM_CONF=$SLURM_CONF"; exit 0; }
      sleep 0.1
    done
    echo "slurm-test-cluster: the node did not become idle in 30 s; logs in $base/log" >&2
    exit 1
    ;;
  stop)
    [ -n "$base" ] || { echo "usage: $0 stop DIR" >&2; exit 2; }
    # Job steps still talking to slurmd keep sockets in the spool; wait (up to 10 s) for them to end.
    for _ in $(seq 1 100); do
      compgen -G "$base/spool/localhost_*" >/dev/null || break
      sleep 0.1
    done
    for daemon in slurmd slurmctld; do
      [ -f "$base/$daemon.child" ] || continue
      pid=$(cat "$base/$daemon.child")
      kill -TERM "$pid" 2>/dev/null || true
      for _ in $(seq 1 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
      rm -f "$base/$daemon.child"
    done
    ;;
  *)
    sed -n '2,10p' "$0" | sed 's/^# \{0,1\}//'
    [ "$mode" = -h ] || [ "$mode" = --help ] || exit 2
    ;;
esac
