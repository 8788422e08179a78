# Sourced by the ros_* tests and bench/ros_latency.sh: a private ROS session in a temporary folder.
#   ros_session_begin        makes $work, starts roscore on a free 127.0.0.1 port (exported
#                            ROS_MASTER_URI; its process group $roscore_pid), stops everything
#                            started with `start` at exit
#   start NAME COMMAND...    runs COMMAND in the background in its own process group, output in
#                            $work/NAME.log; sets $started to its pid
#   file_microphone ECHOPLAN makes the default capture device read a synthesized coffee-mug strike
#                            (ALSA file plugin, raw float32 stereo: the format the stream opens)
# KEEP_WORK=1 in the environment keeps $work (its logs, clips and CSVs) after the session, for
# looking into a failure.
pgids=()
ros_session_end() {
  for g in "${pgids[@]}"; do kill -TERM -- "-$g" 2>/dev/null || true; done
  # roscore stops its rosmaster on TERM, which takes more than a moment on a loaded machine: wait
  # (up to 5 s) for the groups to go before killing what is left.
  local _ g alive
  for _ in $(seq 50); do
    alive=0
    for g in "${pgids[@]}"; do kill -0 -- "-$g" 2>/dev/null && alive=1; done
    [ "$alive" = 0 ] && break
    sleep 0.1
  done
  for g in "${pgids[@]}"; do kill -KILL -- "-$g" 2>/dev/null || true; done
  # roslaunch starts rosmaster and rosout in process groups of their own, which outlive a roscore
  # killed mid-shutdown: whatever still logs under $work is this session's.
  pkill -KILL -f -- "__log:=$work/" 2>/dev/null || true
  wait 2>/dev/null || true
  [ -n "${KEEP_WORK:-}" ] || rm -rf "$work"
}

# Each process in its own process group (setsid), so stopping it stops its children (roscore's
# rosmaster and rosout) and nothing else.
start() {
  local name=$1
  shift
  setsid "$@" >"$work/$name.log" 2>&1 &
  started=$!
  pgids+=("$started")
}

ros_session_begin() {
  work=$(mktemp -d)
  trap ros_session_end EXIT
  export ROS_HOME=$work/ros ROS_LOG_DIR=$work/ros/log ROS_IP=127.0.0.1 ROSCONSOLE_STDOUT_LINE_BUFFERED=1
  local port
  port=$(/usr/bin/python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
  export ROS_MASTER_URI=http://127.0.0.1:$port
  start roscore roscore -p "$port"
  roscore_pid=$started
  for _ in $(seq 100); do rosparam list >/dev/null 2>&1 && return 0; sleep 0.1; done
  echo "roscore on port $port did not come up:"
  cat "$work/roscore.log"
  return 1
}

file_microphone() {
  "$1" synth --object coffee_mug --action strike --seed 5 -o "$work/mic.wav" >/dev/null || return 1
  /usr/bin/python3 - "$work" <<'PY' || return 1
import struct, sys, wave
w = wave.open(sys.argv[1] + "/mic.wav")
n = w.getnframes() * w.getnchannels()
values = struct.unpack("<%dh" % n, w.readframes(w.getnframes()))
open(sys.argv[1] + "/mic.raw", "wb").write(struct.pack("<%df" % n, *[v / 32768 for v in values]))
PY
  cat >"$work/asound.conf" <<CONF
pcm.silent { type null }
pcm.filemic { type file slave.pcm "silent" file "/dev/null" infile "$work/mic.raw" format "raw" }
pcm.!default { type asym capture.pcm "filemic" playback.pcm "silent" }
CONF
  export ALSA_CONFIG_PATH=$work/asound.conf
}
