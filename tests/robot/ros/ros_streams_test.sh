#!/bin/bash
# A robot whose sensors are its joints' efforts and a wrist force-torque sensor, and whose only ROS
# code is its arm driver (docs/real-robot.md, "A robot's joint states and wrench, live"): a real
# roscore on a free 127.0.0.1 port, a stand-in driver (stream_robot_stand_in.py) that serves the
# arm's services and publishes sensor_msgs/JointState and geometry_msgs/WrenchStamped while it
# performs, echoplan_observation computing the model's effort and force features from those
# streams between the planner's markers, echoplan_planner without a listener, and `rosbag record`
# recording the run as a robot's operator would.
#
# Usage: ros_streams_test.sh BUILD_DIR
#
# Checks:
#   - the live trial (actions, observations, beliefs, rewards) equals `echoplan run --data`
#     replaying the recordings tree the driver played, and equals `echoplan run --data` replaying
#     the tree `echoplan import-bag` cuts from the bag of the live run: the same features live, from
#     the recordings and from the bag;
#   - faults of the streams (no joint state in a performance, one lacking a joint, a single one) are
#     each a skipped observation naming the topic and what went wrong, the belief untouched, and
#     the trial goes on to a sort;
#   - echoplan_collector collects a training set from the same driver: every performance's series
#     holds exactly the values the driver published; one lost to a stopped stream is not written,
#     and a second run performs only that one.
set -u
build=$1
here=$(cd "$(dirname "$0")" && pwd)
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
. "$here/ros_session.sh"
ros_session_begin || { fail "roscore"; exit 1; }
export PYTHONPATH=$build/ros/python${PYTHONPATH:+:$PYTHONPATH}

# Three objects pushing back with 1, 1.1 and 1.2 N m, lifted and pressed three times in each of
# four sessions (20 samples at 100 Hz), each performance off its object's load by its own amount per
# channel (Gaussian, from a fixed seed): the classes overlap (about 3 in 4 heard right), so a trial
# senses more than once and both streams count.
/usr/bin/python3 - "$work/tree" <<'PY' || { fail "writing the tree"; exit 1; }
import os, random, sys
root = sys.argv[1]
rng = random.Random(7)
rows = ["file,object,action,session"]
for name, load in (("light", 1.0), ("middle", 1.1), ("heavy", 1.2)):
    for a, action in enumerate(("lift", "press")):
        folder = os.path.join(root, name, action)
        os.makedirs(folder, exist_ok=True)
        for s in range(4):
            for k in range(3):
                stem = os.path.join(folder, f"s{s}_{k}")
                off = [rng.gauss(0, 0.2) for _ in range(3)]
                with open(stem + ".effort.csv", "w") as f:
                    f.write("t,j1,j2\n")
                    for i in range(20):
                        j1 = load * (1 + i / 20) * (1.2 if a == 0 else 1) + off[0] + rng.gauss(0, 0.1)
                        j2 = 0.5 * load + off[1] + rng.gauss(0, 0.1)
                        f.write(f"{i / 100},{j1:.6f},{j2:.6f}\n")
                with open(stem + ".force.csv", "w") as f:
                    f.write("t,force_x,force_y,force_z\n")
                    for i in range(20):
                        fz = -load * (2 - a) + off[2] + rng.gauss(0, 0.1)
                        f.write(f"{i / 100 + 0.005},{rng.gauss(0, 0.05):.6f},{rng.gauss(0, 0.05):.6f},{fz:.6f}\n")
                rows.append(f"{name}/{action}/s{s}_{k}.effort.csv,{name},{action},s{s}")
open(os.path.join(root, "manifest.csv"), "w").write("\n".join(rows) + "\n")
PY
"$build/echoplan" train --data "$work/tree" --series effort=ur5-effort --series force=ur5-force \
  --hold-out session --out "$work/model.json" --problem-out "$work/problem.yaml" >"$work/train.log" 2>&1 \
  || { fail "echoplan train"; cat "$work/train.log"; exit 1; }

object=heavy
session=s2
seed=5
episodes=300
topics=(/joint_states /wrist/wrench /echoplan/performance)
series=(--topic effort=/joint_states --topic force=/wrist/wrench:force)
observation_series=effort=/joint_states,force=/wrist/wrench:force

# run NAME FAULTS SUBSCRIBERS: the stand-in driver, the observation node and the planner (one
# trial of $object); the planner's exit status.
run() {
  local name=$1 faults=$2 subscribers=$3
  start "robot_$name" /usr/bin/python3 "$here/stream_robot_stand_in.py" "$work/tree" $session "$subscribers" "$faults"
  start "observation_$name" "$build/echoplan_observation" _model:="$work/model.json" \
    _series:="$observation_series"
  start "planner_$name" timeout 120 "$build/echoplan_planner" _problem:="$work/problem.yaml" \
    _out:="$work/$name" _seed:=$seed _episodes:=$episodes _trials:=1 _object:=$object _listen:=false \
    _wait_timeout_s:=10
  wait "$started"
}

start bag rosbag record -O "$work/run.bag" "${topics[@]}"
bag_pid=$started
run live "" 2 || { fail "echoplan_planner exited $?"; cat "$work/planner_live.log" "$work/observation_live.log"; }
kill -INT -- "-$bag_pid" 2>/dev/null
for _ in $(seq 100); do [ -f "$work/run.bag" ] && ! [ -f "$work/run.bag.active" ] && break; sleep 0.1; done
[ -f "$work/run.bag" ] || fail "rosbag record wrote no bag: $(cat "$work/bag.log")"

# Columns: trial,step,action,status,heard,probability,observation,p_<object>...,reward,heard_ebr_db,clip.
# A replay has no robot: no status, heard class or probability.
# The replay numbers its trial by the session's place, so the trial column is left out too.
trial0() { cut -d, -f2-3,7- "$1"; }
same_trial() {  # same_trial WHAT REPLAY_DIR
  if ! cmp -s <(trial0 "$work/live/loop_steps.csv") <(trial0 "$2/loop_steps.csv"); then
    fail "the live trial differs from $1"
    diff <(trial0 "$work/live/loop_steps.csv") <(trial0 "$2/loop_steps.csv")
  fi
}
trial_seed=$("$build/tests/robot/ros/feature_rows_reference" trial-seed $seed)
replay() {  # replay TREE SESSION OUT [OPTION...]
  local tree=$1 replayed=$2 out=$3
  shift 3
  "$build/echoplan" run --data "$tree" --object $object --session "$replayed" --model "$work/model.json" \
    --problem "$work/problem.yaml" --seed "$trial_seed" --episodes $episodes --out "$out" "$@" \
    >"$out.log" 2>&1 || { fail "echoplan run --data $tree"; cat "$out.log"; }
}
# The session holds as many performances of each behaviour as the problem allows (the live planner's
# limits): the session's limits are the problem's.
replay "$work/tree" $session "$work/replay"
same_trial "the recordings replayed" "$work/replay"

"$build/echoplan" import-bag "$work/run.bag" -o "$work/bag_tree" "${series[@]}" >"$work/import.log" 2>&1 \
  || { fail "echoplan import-bag"; cat "$work/import.log"; }
# The bag holds only the performances the trial used: planned with the problem's limits, as live.
replay "$work/bag_tree" trial0 "$work/bag_replay" --uses problem
same_trial "its bag replayed" "$work/bag_replay"

sensing=$(grep -c ',\(lift\|press\),' "$work/live/loop_steps.csv")
grep -q "^$sensing performances" "$work/import.log" || fail "the bag does not hold the $sensing performances sensed: $(cat "$work/import.log")"
[ "$sensing" -ge 2 ] || fail "the trial sensed $sensing times: too easy to show the beliefs agree"
sorting=$(awk -F'[][]' '/^  sorting:/ {print $2}' "$work/problem.yaml" | tr -d ' ' | tr ',' '\n')
last_action=$(tail -n 1 "$work/live/loop_steps.csv" | cut -d, -f3)
grep -qx "$last_action" <<<"$sorting" || fail "the live trial ended in '$last_action', not a sorting action"

# The streams' faults, one in each of the first three performances.
stop_all() { for g in "${pgids[@]}"; do [ "$g" = "$roscore_pid" ] || kill -TERM -- "-$g" 2>/dev/null; done; sleep 1; }
stop_all
run faults "1:silent,2:missing,3:short" 1 || { fail "echoplan_planner exited $? under faults"; cat "$work/planner_faults.log"; }
/usr/bin/python3 - "$work/faults/loop_steps.jsonl" <<'PY' || fail "the faults were not skipped observations naming their cause"
import json, sys
steps = [json.loads(line) for line in open(sys.argv[1])]
expected = ["/joint_states: no message during", "/joint_states: a message", "/joint_states: one message during"]
faulty = [s for s in steps if s.get("fault")]
if len(faulty) != 3:
    sys.exit("%d faulty steps, not 3: %s" % (len(faulty), [s.get("fault") for s in steps]))
for s, text in zip(faulty, expected):
    f = s["fault"]
    if not f["observation_skipped"] or text not in f["detail"]:
        sys.exit("step %d: %s (expected a skipped observation saying '%s')" % (s["step"], f, text))
    if s["belief_after"] != s["belief_before"]:
        sys.exit("step %d: the belief moved on a skipped observation" % s["step"])
if "no joint 'j2'" not in faulty[1]["fault"]["detail"]:
    sys.exit("the missing joint is not named: %s" % faulty[1]["fault"])
if steps[-1]["action"] in ("lift", "press"):
    sys.exit("the trial did not end in a sort")
print("3 faults skipped, the trial sorted after %d steps" % len(steps))
PY

# ~series that does not fit the model: exit status 2 before serving, saying why.
for bad in "vision=/camera:vision" "effort=/joint_states,effort=/other"; do
  timeout 20 "$build/echoplan_observation" _model:="$work/model.json" _series:="$bad" \
    __name:=bad_observation >"$work/bad_series.log" 2>&1
  status=$?
  [ "$status" -eq 2 ] || fail "~series $bad: exit status $status, expected 2"
done
grep -q "modality 'effort' named twice" "$work/bad_series.log" || fail "a modality named twice: $(tail -1 "$work/bad_series.log")"
timeout 20 "$build/echoplan_observation" _model:="$work/model.json" _series:=vision=/camera \
  __name:=bad_observation >"$work/bad_series.log" 2>&1
grep -q "no action of the model reads a 'vision' series" "$work/bad_series.log" \
  || fail "a modality the model does not read: $(tail -1 "$work/bad_series.log")"

# A training set collected through the same driver: two objects, two sessions of both behaviours.
# The driver replays the session's first performances in every trial (it restarts per trial).
collect() {  # collect NAME FAULTS: the collector's exit status
  stop_all
  start "robot_$1" /usr/bin/python3 "$here/stream_robot_stand_in.py" "$work/tree" $session 1 "$2"
  start "collector_$1" timeout 120 "$build/echoplan_collector" _objects:=light,heavy \
    _behaviours:=lift,press _sessions:=2 _out:="$work/collected" _listen:=false \
    _series:="$observation_series" _wait_timeout_s:=10
  wait "$started"
}
collect first "2:silent" || fail "echoplan_collector exited $? (first run)"
grep -q "light session 1 press not recorded (run again to perform it): .*/joint_states: no message during 'press'" \
  "$work/collector_first.log" || fail "the lost performance is not reported: $(tail -3 "$work/collector_first.log")"
[ ! -e "$work/collected/light/press/s001.effort.csv" ] || fail "the lost performance was written"
grep -q "7 performances recorded, 0 already there, 1 lost" "$work/collector_first.log" \
  || fail "the first run's summary: $(tail -1 "$work/collector_first.log")"
collect second "" || fail "echoplan_collector exited $? (second run)"
grep -q "1 performances recorded, 7 already there, 0 lost" "$work/collector_second.log" \
  || fail "the second run's summary: $(tail -1 "$work/collector_second.log")"
# The collector's parameters that cannot make a collection: exit status 2, saying why, nothing written.
bad_collector() {  # bad_collector MESSAGE PARAM...
  local message=$1
  shift
  timeout 20 "$build/echoplan_collector" _out:="$work/not_collected" __name:=bad_collector "$@" \
    >"$work/bad_collector.log" 2>&1
  local status=$?
  [ "$status" -eq 2 ] || fail "collector $*: exit status $status, expected 2"
  grep -q -- "$message" "$work/bad_collector.log" || fail "collector $*: no '$message': $(tail -1 "$work/bad_collector.log")"
}
bad_collector "~objects: the parameter is required" _behaviours:=lift
bad_collector "with ~listen false, name the streams to record" _objects:=light _behaviours:=lift _listen:=false
[ ! -e "$work/not_collected" ] || fail "a refused collection wrote $work/not_collected"

/usr/bin/python3 - "$work/tree" "$work/collected" $session <<'PY' || fail "the collected series differ from what the driver published"
import csv, sys
tree, collected, session = sys.argv[1:4]
def values(path):  # the samples' values, row by row (times are when they arrived)
    return [[float(v) for v in row[1:]] for row in list(csv.reader(open(path)))[1:]]
rows = list(csv.DictReader(open(collected + "/manifest.csv")))
assert len(rows) == 8 and all(r["status"] == "done" for r in rows), rows
for r in rows:
    stem = r["file"].rsplit(".", 2)[0]
    assert r["file"].endswith(".effort.csv"), r["file"]
    for modality in ("effort", "force"):
        got = values(f"{collected}/{stem}.{modality}.csv")
        want = values(f"{tree}/{r['object']}/{r['action']}/{session}_0.{modality}.csv")
        assert got == want, (r["file"], modality, got[:2], want[:2])
print("8 performances, each the driver's samples")
PY

if [ "$failures" -eq 0 ]; then
  echo "ros_streams: all checks passed"
else
  for log in "$work"/*.log; do echo "--- $(basename "$log")"; tail -20 "$log"; done
fi
exit "$failures"
