#!/bin/bash
# A robot's own microphone topic: a real roscore on 127.0.0.1 on a free port, a stand-in for audio_capture
# (audio_capture_stand_in.py: audio_common_msgs/AudioData chunks of a known WAV on /robot/audio, paced at
# its rate), echoplan_listener with ~source:=topic on it, and audio_topic_recorder_tests (the recorder
# directly and through the listener: exact samples). Then the listener with bad parameters: exit 2 and a
# message naming the problem.
#
# Usage: audio_topic_test.sh BUILD_DIR
set -u
build=$1
here=$(dirname "$0")
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
. "$here/ros_session.sh"
ros_session_begin || { fail "roscore"; exit 1; }

# 1 s of 16 kHz stereo, frame f = (L(f), R(f)) as audio_topic_recorder_test.cpp states them.
/usr/bin/python3 - "$work/pattern.wav" <<'PY' || { fail "writing the WAV"; exit 1; }
import struct, sys, wave
frames = b"".join(struct.pack("<hh", (173 * f + 12345) % 65536 - 32768, (40503 * f + 999) % 65536 - 32768)
                  for f in range(16000))
with wave.open(sys.argv[1], "wb") as w:
    w.setnchannels(2); w.setsampwidth(2); w.setframerate(16000); w.writeframes(frames)
PY
start audio_capture /usr/bin/python3 "$here/audio_capture_stand_in.py" "$work/pattern.wav" /robot/audio 320
start listener "$build/echoplan_listener" _source:=topic _audio_topic:=/robot/audio _rate:=16000 _channels:=2
# The listener is ready once the master lists it as a subscriber of the stand-in's topic.
listener_subscribed() {
  /usr/bin/python3 -c '
import rosgraph, sys
subscribers = dict(rosgraph.Master("/audio_topic_test").getSystemState()[1])
sys.exit(0 if "/echoplan_listener" in subscribers.get("/robot/audio", []) else 1)' 2>/dev/null
}
for _ in $(seq 100); do listener_subscribed && break; sleep 0.1; done
listener_subscribed || fail "the listener did not subscribe to /robot/audio"

"$build/tests/robot/ros/audio_topic_recorder_tests" || fail "audio_topic_recorder_tests"

# Bad parameters: the listener exits 2 (bad input) and says what is wrong.
# Each under its own name: private parameters stay on the master after a node exits.
rejected=0
check_rejected() {
  local expected=$1
  shift
  rejected=$((rejected + 1))
  timeout 20 "$build/echoplan_listener" __name:=bad_listener_$rejected "$@" >"$work/bad.log" 2>&1
  local status=$?
  [ "$status" -eq 2 ] || fail "listener with $* exited $status, expected 2"
  grep -qF "$expected" "$work/bad.log" || { fail "listener with $*: no '$expected' in its log"; cat "$work/bad.log"; }
}
check_rejected "sample format 'S24LE' on /audio/audio is not supported: only S16LE" _source:=topic _sample_format:=S24LE
check_rejected "sample rate must be >= 1 Hz, got 0" _source:=topic _rate:=0
check_rejected "sample rate must be >= 1 Hz, got -8000" _source:=topic _rate:=-8000
check_rejected "channels must be >= 1, got 0" _source:=topic _channels:=0
check_rejected "is not 'microphone', 'simulation' or 'topic'" _source:=mp3

if [ "$failures" -eq 0 ]; then
  echo "ros_audio_topic: all checks passed"
else
  for log in "$work"/*.log; do echo "--- $(basename "$log")"; tail -20 "$log"; done
fi
exit "$failures"
