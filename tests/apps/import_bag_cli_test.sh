#!/bin/sh
# A haptic-only robot's bags: Debian's rosbag (Python) writes two bags of joint states, wrenches and
# performance markers as a robot's driver would; `echoplan import-bag` cuts them into a recordings
# tree whose files hold exactly the values and times the bags recorded, `train` learns from it,
# and broken bags are refused naming the topic and the message.
# Usage: import_bag_cli_test.sh ECHOPLAN_BINARY SOURCE_DIR
. "$(dirname "$0")/cli_test_lib.sh"

# Three objects pushing back on two joints with 1, 2 and 4 N m, each performed in four sessions of
# two behaviours, 0.3 s at 50 Hz; a joint (j0) no performance reads sits first; a wrench of the
# object's weight. Markers are stamped 1 ms before the first and after the last sample.
# With "missing": the joint states of one message of the second bag lack j2.
write_bags() {
  /usr/bin/python3 - "$@" <<'PY'
import sys, rosbag, rospy
from sensor_msgs.msg import JointState
from geometry_msgs.msg import WrenchStamped
from std_msgs.msg import String
folder, mode = sys.argv[1], sys.argv[2]
t = 100.0
for b, sessions in enumerate(((0, 1), (2, 3))):
    with rosbag.Bag(f"{folder}/run{b}.bag", "w") as bag:
        sent = 0
        for s in sessions:
            for o, (name, load) in enumerate((("light", 1.0), ("middle", 2.0), ("heavy", 4.0))):
                for action in ("lift", "press"):
                    bag.write("/echoplan/performance", String(data=f"start {name} {action} s{s}"), rospy.Time.from_sec(t))
                    for i in range(15):
                        at = rospy.Time.from_sec(t + 0.001 + i / 50)
                        js = JointState(name=["j0", "j1", "j2"], effort=[9.0, load + i / 100 + s / 1000, 0.5 * load])
                        sent += 1
                        if mode == "missing" and b == 1 and sent == 7:
                            js = JointState(name=["j0", "j1"], effort=[9.0, 1.0])
                        bag.write("/joint_states", js, at)
                        w = WrenchStamped()
                        w.wrench.force.z = -load * (2 if action == "lift" else 1)
                        bag.write("/wrist/wrench", w, at)
                    bag.write("/echoplan/performance", String(data="end"), rospy.Time.from_sec(t + 0.3))
                    t += 1.0
PY
}
mkdir -p "$work/bags"
write_bags "$work/bags" good || fail "writing the bags"

"$bin" import-bag "$work/bags/run0.bag" "$work/bags/run1.bag" -o "$work/tree" \
  --topic effort=/joint_states --topic force=/wrist/wrench:force >"$work/import.out" 2>&1 \
  || { fail "import-bag exited $?"; cat "$work/import.out"; }
grep -q "^24 performances" "$work/import.out" || { fail "not 24 performances"; cat "$work/import.out"; }
[ "$(wc -l <"$work/tree/manifest.csv")" -eq 25 ] || fail "the manifest does not list 24 performances"
grep -q "^heavy/press/003.effort.csv,heavy,press,s3$" "$work/tree/manifest.csv" \
  || { fail "heavy's fourth press is not listed as session s3"; cat "$work/tree/manifest.csv"; }
# Session s1's light lift (the second of light/lift): 15 samples from 0.001 s, j1 = 1 + i/100 + 0.001.
/usr/bin/python3 - "$work/tree" <<'PY' || fail "the imported series differ from what the bag recorded"
import csv, sys
rows = list(csv.reader(open(f"{sys.argv[1]}/light/lift/001.effort.csv")))
assert rows[0] == ["t", "j0", "j1", "j2"], rows[0]
assert len(rows) == 16, len(rows)
for i, r in enumerate(rows[1:]):
    assert abs(float(r[0]) - (0.001 + i / 50)) < 1e-6, r
    assert abs(float(r[2]) - (1.0 + i / 100 + 0.001)) < 1e-12, r
    assert float(r[1]) == 9.0 and float(r[3]) == 0.5, r
force = list(csv.reader(open(f"{sys.argv[1]}/heavy/lift/000.force.csv")))
assert force[0] == ["t", "force_x", "force_y", "force_z"], force[0]
assert all(float(r[3]) == -8.0 for r in force[1:]), force[1]
PY

"$bin" train --data "$work/tree" --series "effort=bins(3,mean)[j1,j2]" --series "force=stats[force_z]" \
  --hold-out session --out "$work/model.json" >"$work/train.out" 2>&1 \
  || { fail "train on the imported tree exited $?"; cat "$work/train.out"; }
grep -q "effort 1.000" "$work/train.out" || { fail "the efforts do not tell the objects apart"; cat "$work/train.out"; }

mkdir -p "$work/bad"
write_bags "$work/bad" missing || fail "writing the bad bags"
expect_input_error "a joint state without one of the joints" "topic /joint_states message 7: no joint 'j2'" \
  import-bag "$work/bad/run0.bag" "$work/bad/run1.bag" -o "$work/bad_tree" --topic effort=/joint_states
grep -q "run1.bag" "$work/err" || fail "the error does not name the bag"
expect_input_error "a topic the bag does not have" "no messages on topic /wrench" \
  import-bag "$work/bags/run0.bag" -o "$work/t2" --topic force=/wrench
expect_input_error "a wrench read as a joint state field" "its field is force, torque or wrench" \
  import-bag "$work/bags/run0.bag" -o "$work/t3" --topic force=/wrist/wrench:effort
expect_input_error "not a bag" "not a readable ROS 1 bag" \
  import-bag "$work/tree/manifest.csv" -o "$work/t4" --topic effort=/joint_states
expect_input_error "a malformed --topic" "expected MODALITY=TOPIC" \
  import-bag "$work/bags/run0.bag" -o "$work/t5" --topic /joint_states
expect_input_error "nothing to import" "nothing to import" import-bag "$work/bags/run0.bag" -o "$work/t6"

# A robot's microphone in a bag (audio_common_msgs, as audio_capture publishes it): two performances,
# each a few 100-frame stereo chunks between its markers (a chunk before the first start is not in
# it), the format latched on /audio/audio_info. "noinfo": the same without the format; "odd": one
# chunk of 101 bytes.
write_audio_bag() {
  /usr/bin/python3 - "$src/tests/robot/ros" "$@" <<'PY'
import struct, sys
sys.path.insert(0, sys.argv[1])
import rosbag, rospy
from audio_capture_stand_in import AudioData, AudioInfo
from std_msgs.msg import String
path, mode = sys.argv[2], sys.argv[3]
def chunk(first):  # 100 stereo frames: left counts up from `first`, right is minus left
    return b"".join(struct.pack("<hh", first + i, -(first + i)) for i in range(100))
with rosbag.Bag(path, "w") as bag:
    if mode != "noinfo":
        bag.write("/audio/audio_info", AudioInfo(2, 16000, "S16LE", 0, "wave"), rospy.Time.from_sec(10))
    bag.write("/audio/audio", AudioData(chunk(-5000)), rospy.Time.from_sec(10.5))
    t = 11.0
    for p, (obj, action, chunks) in enumerate((("mug", "strike", 3), ("cup", "slide", 2))):
        bag.write("/echoplan/performance", String(data=f"start {obj} {action} s1"), rospy.Time.from_sec(t))
        for c in range(chunks):
            data = chunk(1000 * p + 100 * c)
            if mode == "odd" and p == 1:
                data = data[:101]
            bag.write("/audio/audio", AudioData(data), rospy.Time.from_sec(t + 0.01 + 0.00625 * c))
        bag.write("/echoplan/performance", String(data="end"), rospy.Time.from_sec(t + 0.5))
        t += 1.0
PY
}
write_audio_bag "$work/audio.bag" good || fail "writing the audio bag"
"$bin" import-bag "$work/audio.bag" -o "$work/audio_tree" --audio /audio/audio >"$work/audio.out" 2>&1 \
  || { fail "import-bag --audio exited $?"; cat "$work/audio.out"; }
grep -q "^mug/strike/000.wav,mug,strike,s1$" "$work/audio_tree/manifest.csv" \
  || { fail "the strike's WAV is not listed"; cat "$work/audio_tree/manifest.csv"; }
/usr/bin/python3 - "$work/audio_tree" <<'PY' || fail "the WAVs do not hold exactly the chunks of their performances"
import struct, sys, wave
for name, first, frames in (("mug/strike/000.wav", 0, 300), ("cup/slide/000.wav", 1000, 200)):
    with wave.open(f"{sys.argv[1]}/{name}") as w:
        assert (w.getframerate(), w.getnchannels(), w.getsampwidth()) == (16000, 2, 2), name
        samples = struct.unpack("<%dh" % (2 * w.getnframes()), w.readframes(w.getnframes()))
    want = []
    for c in range(frames // 100):
        for i in range(100):
            v = first + 100 * c + i
            want += [v, -v]
    assert list(samples) == want, (name, samples[:4], want[:4])
PY
write_audio_bag "$work/noinfo.bag" noinfo || fail "writing the bag without format"
expect_input_error "audio without its format" "no messages on topic /audio/audio_info, where the format of the audio on /audio/audio must be" \
  import-bag "$work/noinfo.bag" -o "$work/t7" --audio /audio/audio
write_audio_bag "$work/odd.bag" odd || fail "writing the bag with an odd chunk"
expect_input_error "a chunk that is not whole frames" "topic /audio/audio message 5: 101 bytes, not a whole number of S16LE frames of 2 channel(s)" \
  import-bag "$work/odd.bag" -o "$work/t8" --audio /audio/audio
finish import-bag
