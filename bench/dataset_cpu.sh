#!/bin/bash
# CPU cost of `echoplan synth-recordings` end to end, two binaries compared in one run: A and B alternated
# (A B A B ...) so both see the same machine load, CPU time (user + sys, /usr/bin/time) and wall time
# of each run, medians, and B's median CPU over A's. Each run writes the 48 recordings (161 s of audio)
# of the four original objects, 6 per object and action, seed 1; the last run's folders of A and B are
# compared with diff -r (a pure optimisation writes the same bytes).
#
#   bench/dataset_cpu.sh BINARY_A BINARY_B [RUNS] [THREADS]
#
# RUNS: runs of each binary (default 9); THREADS: --threads (default 1: CPU per core).
# Run from the repository root (its objects/ and problems/ are the data). Needs /usr/bin/time and
# Debian's python3. Results: docs/BENCHMARKS.md ("Simulator").
set -eu
if [ $# -lt 2 ]; then
  sed -n '2,12p' "$0"
  exit 2
fi
a=$1
b=$2
runs=${3:-9}
threads=${4:-1}
export ECHOPLAN_DATA_DIR=${ECHOPLAN_DATA_DIR:-$PWD}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT INT TERM
for run in $(seq "$runs"); do
  for which in A B; do
    if [ "$which" = A ]; then binary=$a; else binary=$b; fi
    rm -rf "$work/$which"
    /usr/bin/time -f "%U %S %e" -o "$work/time" "$binary" synth-recordings --per-pair 6 --seed 1 \
      -o "$work/$which" --threads "$threads" \
      --objects pringles_can,coffee_mug,plastic_cup,paper_base > /dev/null 2>&1
    echo "$which $(cat "$work/time")" >> "$work/times"
  done
done
/usr/bin/python3 - "$work/times" "$a" "$b" <<'EOF'
import statistics, sys
runs = {"A": [], "B": []}
for line in open(sys.argv[1]):
    which, user, system, wall = line.split()
    runs[which].append((float(user) + float(system), float(wall)))
for which, binary in (("A", sys.argv[2]), ("B", sys.argv[3])):
    cpu = [r[0] for r in runs[which]]
    print(f"{which} {binary}: CPU s median {statistics.median(cpu):.3f} "
          f"[{' '.join(f'{c:.2f}' for c in cpu)}], wall s median "
          f"{statistics.median(r[1] for r in runs[which]):.3f}")
ratio = statistics.median(r[0] for r in runs["B"]) / statistics.median(r[0] for r in runs["A"])
print(f"CPU ratio B/A (medians): {ratio:.3f}")
EOF
if diff -r "$work/A" "$work/B" > /dev/null; then
  echo "files: identical (diff -r)"
else
  echo "files: DIFFERENT"
fi
uptime
