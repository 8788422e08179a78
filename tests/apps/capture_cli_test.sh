#!/bin/sh
# `echoplan devices` and `echoplan record` end to end, on a capture device that reads a file (a private
# ALSA configuration, no sound card): the WAV written holds exactly the file's samples; bad flags exit 2.
# Usage: capture_cli_test.sh ECHOPLAN_BINARY SOURCE_DIR
. "$(dirname "$0")/cli_test_lib.sh"

# 1 s of stereo 16-bit noise, as the raw float32 the stream opens with and as the 16-bit PCM we expect.
/usr/bin/python3 - "$work" <<'PY'
import random, struct, sys
random.seed(5)
values = [random.randint(-32768, 32767) for _ in range(2 * 44100)]
open(sys.argv[1] + "/in.raw", "wb").write(struct.pack("<%df" % len(values), *[v / 32768 for v in values]))
open(sys.argv[1] + "/expected.pcm", "wb").write(struct.pack("<%dh" % len(values), *values))
PY
cat >"$work/asound.conf" <<CONF
pcm.silent { type null }
pcm.filemic { type file slave.pcm "silent" file "/dev/null" infile "$work/in.raw" format "raw" }
pcm.!default { type asym capture.pcm "filemic" playback.pcm "silent" }
CONF
export ALSA_CONFIG_PATH="$work/asound.conf"

"$bin" devices >"$work/devices" 2>/dev/null || fail "devices exited $?"
grep -q '^\* \[[0-9]*\] default (ALSA' "$work/devices" || { fail "devices does not mark the default input"; cat "$work/devices"; }
grep -q 'filemic' "$work/devices" || fail "devices does not list filemic"

"$bin" record --seconds 0.25 --device filemic -o "$work/clip.wav" >"$work/out" 2>"$work/err" \
  || { fail "record exited $?"; cat "$work/err"; }
grep -q "wrote $work/clip.wav (0.250 s, 2 channels, 44100 Hz)" "$work/out" || { fail "record output"; cat "$work/out"; }
/usr/bin/python3 - "$work" <<'PY' || fail "the WAV's samples differ from the device's file"
import sys, wave
w = wave.open(sys.argv[1] + "/clip.wav")
assert (w.getnchannels(), w.getframerate(), w.getsampwidth(), w.getnframes()) == (2, 44100, 2, 11025), w.getparams()
data = w.readframes(11025)
assert data == open(sys.argv[1] + "/expected.pcm", "rb").read()[:len(data)], "samples differ"
PY

expect_input_error "unknown device" "no input device 'nope'" record --device nope -o "$work/x.wav"
expect_input_error "unsupported rate" "cannot record 2 channels at 3000000 Hz" record --rate 3000000 -o "$work/x.wav"
expect_input_error "zero seconds" "seconds must be > 0" record --seconds 0 -o "$work/x.wav"
expect_input_error "missing output" "output is required" record
[ ! -e "$work/x.wav" ] || fail "a failed record wrote a file"

finish "capture CLI"
