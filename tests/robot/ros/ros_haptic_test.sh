#!/bin/bash
# A robot without a microphone over ROS (docs/real-robot.md, "A robot without a microphone"): a real
# roscore on a free 127.0.0.1 port, a stand-in robot (haptic_robot_stand_in.py: serves the arm's
# services and publishes one haptic row per performance on /echoplan/features), echoplan_observation
# serving a model trained on the haptic rows alone, and echoplan_planner with ~listen false (no
# listener runs).
#
# Usage: ros_haptic_test.sh BUILD_DIR SOURCE_DIR
#
# Checks:
#   - every observation the node answered equals ObservationModel::classify_rows on the row the
#     robot published for that performance, computed in process (feature_rows_reference): label,
#     unknown, the probability and every class's probability, as the same doubles;
#   - the trial (actions, observations, beliefs, rewards) equals `echoplan run --data` replaying the
#     same session with the same seed, and ends in a sorting action;
#   - a request whose row never comes is answered after ~feature_wait_s with an error naming the
#     sensor, the behaviour and the topic, and a misnamed row is named in it; the node serves the
#     next request.
set -u
build=$1
source_dir=$2
here=$(cd "$(dirname "$0")" && pwd)
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
. "$here/ros_session.sh"
ros_session_begin || { fail "roscore"; exit 1; }
export PYTHONPATH=$build/ros/python${PYTHONPATH:+:$PYTHONPATH}

# The shipped feature set's haptic rows alone: a robot that has only that sensor.
data=$work/haptic
for behaviour in "$source_dir"/experiments/data/synthetic_objects/*/; do
  mkdir -p "$data/$(basename "$behaviour")"
  cp "$behaviour/haptic.csv" "$data/$(basename "$behaviour")/"
done
"$build/echoplan" train --data "$data" --out "$work/model.json" --problem-out "$work/problem.yaml" \
  >"$work/train.log" 2>&1 || { fail "echoplan train"; cat "$work/train.log"; exit 1; }

object=obj3
session=s0 # the object's first session: trial 0 of `echoplan run --data`, as the planner's trial 0
seed=5
episodes=300
start robot /usr/bin/python3 "$here/haptic_robot_stand_in.py" "$data" haptic $session "$work/published.csv"
start observation "$build/echoplan_observation" _model:="$work/model.json" _feature_wait_s:=2
start planner timeout 120 "$build/echoplan_planner" _problem:="$work/problem.yaml" _out:="$work/ros_run" \
  _seed:=$seed _episodes:=$episodes _trials:=2 _object:=$object _listen:=false _wait_timeout_s:=10
wait "$started"
status=$?
[ "$status" -eq 0 ] || { fail "echoplan_planner exited $status"; cat "$work/planner.log"; }

# The node's answers against the model's own decision on the published rows.
"$build/tests/robot/ros/feature_rows_reference" classify "$work/model.json" "$work/published.csv" \
  >"$work/expected.txt" || fail "feature_rows_reference classify"
/usr/bin/python3 - "$work/ros_run/loop_steps.jsonl" "$work/expected.txt" <<'PY' || fail "observations differ from classify_rows"
import json, sys
steps = [json.loads(line) for line in open(sys.argv[1])]
heard = [s for s in steps if "heard" in s]
expected = [line.split() for line in open(sys.argv[2])]
if not heard or len(heard) != len(expected):
    sys.exit("%d observations over ROS, %d rows published" % (len(heard), len(expected)))
for s, e in zip(heard, expected):
    h = s["heard"]
    want = {"action": e[0], "label": e[1], "unknown": e[2] == "1", "probability": float(e[3]),
            "probabilities": {k: float(v) for k, v in (c.split("=") for c in e[4:])}}
    got = {"action": s["action"], "label": h["label"], "unknown": h["unknown"],
           "probability": h["probability"], "probabilities": h["probabilities"]}
    if got != want:
        sys.exit("step %d: over ROS %s, classify_rows %s" % (s["step"], got, want))
    if s["observation"] != h["label"]:
        sys.exit("step %d: observation %s, heard %s" % (s["step"], s["observation"], h["label"]))
print("%d observations equal classify_rows on the published rows" % len(heard))
PY

# Trial 0 replayed in process from the recorded session, with the planner's trial seed (trial 1
# has streams of its own; `echoplan run` runs one trial).
trial_seed=$("$build/tests/robot/ros/feature_rows_reference" trial-seed $seed)
"$build/echoplan" run --data "$data" --object $object --session $session --model "$work/model.json" \
  --problem "$work/problem.yaml" --seed "$trial_seed" --episodes $episodes --out "$work/replay" \
  >"$work/replay.log" 2>&1 || { fail "echoplan run --data"; cat "$work/replay.log"; }
# Columns: trial,step,action,status,heard,probability,observation,p_<object>...,reward,heard_ebr_db,clip. A replay
# has no robot: no status, heard class or probability (compared above instead).
trial0() { grep -v '^1,' "$1" | cut -d, -f1-3,7-; }
if ! cmp -s <(trial0 "$work/ros_run/loop_steps.csv") <(trial0 "$work/replay/loop_steps.csv"); then
  fail "trial 0 over ROS differs from echoplan run --data"
  diff <(trial0 "$work/ros_run/loop_steps.csv") <(trial0 "$work/replay/loop_steps.csv")
fi
sorting=$(awk -F'[][]' '/^  sorting:/ {print $2}' "$work/problem.yaml" | tr -d ' ' | tr ',' '\n')
for t in 0 1; do
  steps=$(grep -c "^$t," "$work/ros_run/loop_steps.csv")
  last_action=$(grep "^$t," "$work/ros_run/loop_steps.csv" | tail -n 1 | cut -d, -f3)
  grep -qx "$last_action" <<<"$sorting" || fail "trial $t ended in '$last_action', not a sorting action"
  [ "$steps" -ge 2 ] || fail "trial $t sorted without sensing"
done
ls "$work/ros_run/clips" 2>/dev/null | grep -q . && fail "clips were saved without a microphone"

# A request whose row never comes, with a misnamed row on the topic: a clear error in time; then a
# request whose row comes is served.
/usr/bin/python3 - >"$work/missing.txt" 2>&1 <<'PY' || fail "the missing-row request: $(cat "$work/missing.txt")"
import time
import rospy
from echoplan_ros.msg import FeatureRow
from echoplan_ros.srv import Observe
rospy.init_node("missing_row_client", disable_signals=True)
features = rospy.Publisher("/echoplan/features", FeatureRow, queue_size=4)
deadline = time.time() + 10
while features.get_num_connections() == 0 and time.time() < deadline:
    time.sleep(0.01)
features.publish(FeatureRow("press", "haptics", [1.0, 2.0, 3.0]))
time.sleep(0.5)  # delivered before the request
rospy.wait_for_service("/echoplan/observe", 10)
t0 = time.time()
answer = rospy.ServiceProxy("/echoplan/observe", Observe)(action="press")
took = time.time() - t0
print(answer.error)
assert 1.9 <= took < 5, "answered after %.1f s" % took
assert answer.label == "" and not answer.classes, "an observation came with the error"
features.publish(FeatureRow("press", "haptic", [0.5, -0.25, 1.0]))
answer = rospy.ServiceProxy("/echoplan/observe", Observe)(action="press")
assert answer.error == "" and answer.label in answer.classes, "not served after the error: %s" % answer
PY
for text in "/echoplan/features: no 'haptic' row of 'press' arrived within 2 s" \
  "ignored: a 'haptics' row of 'press': the model's sensors for 'press' are: haptic"; do
  grep -qF "$text" "$work/missing.txt" || fail "the error does not say \"$text\": $(cat "$work/missing.txt")"
done
grep -q "a 'haptics' row of 'press'.*ignored" "$work/observation.log" || fail "the node did not log the misnamed row"

if [ "$failures" -eq 0 ]; then
  echo "ros_haptic: all checks passed"
else
  for log in "$work"/*.log; do echo "--- $(basename "$log")"; tail -20 "$log"; done
fi
exit "$failures"
