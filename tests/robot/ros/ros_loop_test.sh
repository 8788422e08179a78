#!/bin/bash
# The ROS 1 loop end to end: a real roscore on 127.0.0.1 on a free port, echoplan_sim_robot,
# echoplan_listener, echoplan_observation and echoplan_planner, compared with the in-process loop.
#
# Usage: ros_loop_test.sh CASE BUILD_DIR
#   sim               the all-simulated layout (listener hears the simulated robot's clips): the trials
#                     end in a sorting action and loop_steps.csv equals the in-process loop's, byte for byte
#   mic               the listener records from a capture device that reads a file (private ALSA
#                     configuration): same comparison, with the in-process loop on the same device.
#                     The device delivers the file from its first frame faster than real time, so
#                     what it guarantees is the file's first 0.5 s to a recording that runs to its
#                     limit; one stopped earlier holds a prefix whose length is up to the scheduler.
#                     Both sides therefore record exactly 0.5 s (~min_seconds = ~max_seconds) and
#                     every clip, an aborted action's too, must be the same bytes
#   run               the all-simulated layout with the planner told the true object: its log equals
#                     `echoplan run --object` (the in-process loop's command), byte for byte
#   torque            as run, with a model of sound, joint torques and wrist force (trained on
#                     `synth-recordings --signals audio,effort,force`): the simulated robot publishes
#                     its sensors (~sensors) as JointState and WrenchStamped, the observation node
#                     cuts them between the planner's markers (~series), and the log equals `echoplan
#                     run`'s, whose simulated world computes the same rows from its physics in process
#   levels            as run, planning with observations graded by each recording's level
#                     (problem-levels.yaml): the level grade crosses the observation service, every
#                     heard observation is `<class>@<level>`, and the log equals `echoplan run`'s
#   launch            the all-simulated layout started by simulated_layout.launch: same comparison
#   kill_observation  the observation node is killed mid-trial and not restarted: the performance it
#                     was hearing goes unheard, and the planner stops once the service has not come
#                     back within its wait (10 s) with a logged failure naming the service, exit
#                     status 1, the finished steps kept
#   restart_observation
#                     the observation node dies during its first call (a stand-in that exits on the
#                     request) and the real one is started a second later: that performance goes
#                     unheard (one fault in loop_steps.jsonl), the planner waits for the service,
#                     re-plans, and every trial ends in a sorting action
#   restart_listener  the listener is killed after the first step and started again a second later:
#                     the run goes on (a recording it was making goes unheard; a kill between
#                     recordings costs only the wait), every trial ends in a sorting action
#   restart_master    the ROS master (roscore) is killed with SIGKILL after the first step and
#                     started again on the same port a second later: every node registers with the
#                     new master again (it lists each one's services and topics), the run goes on
#                     and every trial ends in a sorting action (a performance heard across the
#                     outage may go unheard: at most one skipped observation); a planner started
#                     after it finds every node through the new master
#   kill_master       the master is killed after the first step and not started again: the planner
#                     stops with exit status 1 and a logged failure naming the master
#   retry_safe        the arm's first sorting action fails with retry_safe (flaky_arm_stand_in.py
#                     in front of the simulated robot): the loop repeats it (attempts 2 in
#                     loop_steps.jsonl) and every trial ends in a sorting action
#   fail_unsafe       the same failure without retry_safe: that trial ends as failed, the others sort
set -u
case_name=$1
build=$2
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
. "$(dirname "$0")/ros_session.sh"
ros_session_begin || { fail "roscore"; exit 1; }

"$build/tests/robot/ros/ros_loop_reference" prepare "$work" || { fail "preparing the model"; exit 1; }
seed=3
episodes=300
trials=2
source=simulation
listener_params=()
if [ "$case_name" = mic ]; then
  source=microphone
  listener_params=(_min_seconds:=0.5)
  file_microphone "$build/echoplan" || { fail "making the file-backed microphone"; exit 1; }
fi
case "$case_name" in kill_* | restart_* | retry_safe | fail_unsafe) trials=3 ;; esac
object_param=()
problem=$work/problem.yaml
model=$work/model.json
sim_params=()
observation_params=()
if [ "$case_name" = run ] || [ "$case_name" = levels ] || [ "$case_name" = torque ]; then
  trials=1
  object_param=(_object:=coffee_mug)
fi
[ "$case_name" = levels ] && problem=$work/problem-levels.yaml
if [ "$case_name" = torque ]; then
  source_dir=$(cd "$(dirname "$0")/../../.." && pwd)
  "$build/echoplan" synth-recordings --per-pair 3 --seed 2 --signals audio,effort,force -o "$work/torque_tree" \
    >"$work/torque_synth.log" 2>&1 || { fail "synth-recordings"; cat "$work/torque_synth.log"; exit 1; }
  "$build/echoplan" train --data "$work/torque_tree" --series effort=ur5-effort --series force=ur5-force \
    --problem-base "$source_dir/problems/audio_objects.yaml" --out "$work/torque.json" \
    --problem-out "$work/torque.yaml" >"$work/torque_train.log" 2>&1 \
    || { fail "train"; cat "$work/torque_train.log"; exit 1; }
  model=$work/torque.json
  problem=$work/torque.yaml
  sim_params=(_sensors:=true)
  observation_params=(_series:=effort=/joint_states,force=/wrist/wrench:force)
fi

if [ "$case_name" = launch ]; then
  # The all-simulated layout as its launch file starts it (the package the build makes in build/ros).
  ROS_PACKAGE_PATH=$build/ros setsid timeout 120 roslaunch "$build/ros/echoplan/launch/simulated_layout.launch" \
    model:="$work/model.json" problem:="$work/problem.yaml" out:="$work/ros_run" trials:=$trials seed:=$seed \
    episodes:=$episodes >"$work/planner.log" 2>&1 &
  planner_pid=$!
  pgids+=("$planner_pid")
else
  if [ "$case_name" = retry_safe ] || [ "$case_name" = fail_unsafe ]; then
    # The stand-in serves ExecuteAction and passes it on to the simulated robot under another name.
    start sim_robot "$build/echoplan_sim_robot" /echoplan/execute_action:=/sim/execute_action
    retry_safe=false
    [ "$case_name" = retry_safe ] && retry_safe=true
    PYTHONPATH=$build/ros/python${PYTHONPATH:+:$PYTHONPATH} \
      start flaky_arm /usr/bin/python3 "$(dirname "$0")/flaky_arm_stand_in.py" $retry_safe
  else
    # restart_master: actions that take a while, so the run outlasts the master's restart.
    case "$case_name" in *_master) sim_params=(_min_duration_s:=0.4) ;; esac
    start sim_robot "$build/echoplan_sim_robot" "${sim_params[@]}"
  fi
  start listener "$build/echoplan_listener" _source:=$source _max_seconds:=0.5 "${listener_params[@]}"
  listener_pid=$started
  if [ "$case_name" = restart_observation ]; then
    # An observation node that dies during its first call (dying_observation_stand_in.py).
    PYTHONPATH=$build/ros/python${PYTHONPATH:+:$PYTHONPATH} \
      start observation /usr/bin/python3 "$(dirname "$0")/dying_observation_stand_in.py"
  else
    start observation "$build/echoplan_observation" _model:="$model" "${observation_params[@]}"
  fi
  observation_pid=$started
  start planner timeout 120 "$build/echoplan_planner" _problem:="$problem" _out:="$work/ros_run" \
    _seed:=$seed _episodes:=$episodes _trials:=$trials _wait_timeout_s:=10 "${object_param[@]}"
  planner_pid=$started
fi
if [ "$case_name" = kill_observation ]; then
  # Kill the observation node once it has answered its first request.
  for _ in $(seq 300); do grep -q "heard" "$work/observation.log" && break; sleep 0.05; done
  { kill -KILL "$observation_pid"; wait "$observation_pid"; } 2>/dev/null
  killed_at=$(date +%s.%N)
fi
if [ "$case_name" = restart_observation ]; then
  # Once the stand-in has died mid-call, the real node comes up a second later.
  wait "$observation_pid" 2>/dev/null
  sleep 1
  start observation_again "$build/echoplan_observation" _model:="$work/model.json"
fi
if [ "$case_name" = restart_listener ]; then
  # Once a step is logged, kill the listener (its whole process group) and start it a second later.
  for _ in $(seq 600); do [ "$(cat "$work/ros_run/loop_steps.csv" 2>/dev/null | wc -l)" -ge 2 ] && break; sleep 0.05; done
  { kill -KILL -- "-$listener_pid"; wait "$listener_pid"; } 2>/dev/null
  sleep 1
  start listener_again "$build/echoplan_listener" _source:=$source _max_seconds:=0.5
fi
# Whether the master knows every echoplan node's services and topics (what a node started now would
# look up); prints what it lacks.
check_registrations() {
  /usr/bin/python3 - <<'PY'
import sys
import rosgraph
publishers, subscribers, services = rosgraph.Master("/ros_loop_test").getSystemState()
known = {("pub", t, n) for t, ns in publishers for n in ns} | {("sub", t, n) for t, ns in subscribers for n in ns} \
    | {("srv", t, n) for t, ns in services for n in ns}
wanted = [("srv", "/echoplan/execute_action", "/echoplan_sim_robot"), ("srv", "/echoplan/begin_trial", "/echoplan_sim_robot"),
          ("pub", "/echoplan/sim_clip", "/echoplan_sim_robot"), ("srv", "/echoplan/observe", "/echoplan_observation"),
          ("sub", "/echoplan/sim_clip", "/echoplan_listener"), ("pub", "/echoplan/clip", "/echoplan_listener"),
          ("pub", "/echoplan/recording", "/echoplan_listener"), ("sub", "/echoplan/clip", "/echoplan_planner"),
          ("sub", "/echoplan/recording", "/echoplan_planner")]
missing = [w for w in wanted if w not in known]
for kind, name, node in missing:
    print("the restarted master does not know %s's %s %s" % (node, {"pub": "publisher of", "sub": "subscriber to", "srv": "service"}[kind], name))
sys.exit(1 if missing else 0)
PY
}

if [ "$case_name" = restart_master ] || [ "$case_name" = kill_master ]; then
  # Once a step is logged, kill the master and start it again on the same port a second later:
  # roscore's roslaunch and the rosmaster and rosout it started (in process groups of their own, so
  # by the pids it logged).
  for _ in $(seq 600); do [ "$(cat "$work/ros_run/loop_steps.csv" 2>/dev/null | wc -l)" -ge 2 ] && break; sleep 0.05; done
  core_pids=$(grep -o 'process\[\(master\|rosout-1\)\]: started with pid \[[0-9]*\]' "$work/roscore.log" | grep -o '[0-9]*\]$' | tr -d ']')
  { kill -KILL -- "-$roscore_pid" $core_pids; wait "$roscore_pid"; } 2>/dev/null
  echo "killed the master (roscore $roscore_pid, rosmaster and rosout:" $core_pids") after step 1"
  killed_at=$(date +%s.%N)
fi
if [ "$case_name" = restart_master ]; then
  sleep 1
  start roscore_again roscore -p "${ROS_MASTER_URI##*:}"
  echo "started the master again on ${ROS_MASTER_URI}"
  # Each node notices within a second or so of the master answering and registers again; asked while
  # the planner still runs (it unregisters when it exits). A loaded machine under the sanitizers takes
  # seconds to start roscore alone, hence the long wait.
  for _ in $(seq 300); do
    [ "$(cat "$work"/{sim_robot,listener,observation,planner}.log | grep -c 'restarted; registered')" -ge 4 ] && break
    sleep 0.1
  done
  echo "the nodes registered again $(/usr/bin/python3 -c "import time; print(round(time.time() - $killed_at, 1))") s after the kill"
  for node in sim_robot listener observation planner; do
    grep -q "restarted; registered" "$work/$node.log" \
      || { fail "echoplan_$node did not say it registered again; its log ends:"; tail -8 "$work/$node.log"; }
  done
  check_registrations >"$work/registrations.log" 2>&1 || { fail "the new master lacks registrations"; cat "$work/registrations.log"; }
  kill -0 "$planner_pid" 2>/dev/null || fail "the planner ended before the registrations were checked (the run is too short)"
fi
wait "$planner_pid"
status=$?

case "$case_name" in
  sim | mic | launch | run | levels | torque)
    [ "$status" -eq 0 ] || { fail "echoplan_planner exited $status"; cat "$work/planner.log"; }
    ref_source=sim
    [ "$case_name" = mic ] && ref_source=mic
    if [ "$case_name" = run ] || [ "$case_name" = levels ] || [ "$case_name" = torque ]; then
      "$build/echoplan" run --object coffee_mug --problem "$problem" --model "$model" \
        --seed $seed --episodes $episodes --out "$work/in_process" >"$work/reference.log" 2>&1 \
        || { fail "echoplan run failed"; cat "$work/reference.log"; }
    else
      "$build/tests/robot/ros/ros_loop_reference" run "$work" "$work/in_process" $ref_source $seed $episodes $trials \
        0.5 >"$work/reference.log" 2>&1 || { fail "the in-process reference failed"; cat "$work/reference.log"; }
    fi
    if ! cmp -s "$work/ros_run/loop_steps.csv" "$work/in_process/loop_steps.csv"; then
      fail "loop_steps.csv over ROS differs from the in-process loop's"
      diff "$work/ros_run/loop_steps.csv" "$work/in_process/loop_steps.csv"
    fi
    if [ "$case_name" = levels ]; then
      # Column 7 is the planner's observation (trial,step,action,status,heard,probability,observation):
      # every sensing step's is a class at a level.
      unlevelled=$(awk -F, 'NR > 1 && $3 !~ /^move_to_/ && $7 !~ /@(noisy|fair|clear)$/ {n++} END {print n + 0}' \
        "$work/ros_run/loop_steps.csv")
      [ "$unlevelled" -eq 0 ] || { fail "$unlevelled heard observations carry no level"; cat "$work/ros_run/loop_steps.csv"; }
    fi
    # Every trial ends in a sorting action. The file-backed microphone plays one strike recording on, 0.5 s
    # per capture, whatever the action: it carries no evidence of the object, so there a trial may also end
    # in the world's terminal outcome (the object slid out of reach: `failed`), which the log must show.
    if [ "$case_name" = mic ]; then
      ended=$(awk -F, 'NR > 1 && ($3 ~ /^move_to_/ || $4 == "failed" || $4 == "collision") {n++} END {print n + 0}' \
        "$work/ros_run/loop_steps.csv")
    else
      ended=$(awk -F, 'NR > 1 && $3 ~ /^move_to_/ {n++} END {print n + 0}' "$work/ros_run/loop_steps.csv")
    fi
    [ "$ended" -eq "$trials" ] || { fail "$ended of $trials trials ended in a sorting action (or, mic: a terminal outcome)"; cat "$work/ros_run/loop_steps.csv"; }
    # The recorded clips are the same audio, every one (mic: each exactly the file's first 0.5 s).
    clips=0
    for clip in "$work"/in_process/clips/*.wav; do
      clips=$((clips + 1))
      cmp -s "$clip" "$work/ros_run/clips/$(basename "$clip")" || fail "clip $(basename "$clip") differs"
    done
    named=$(awk -F, 'NR > 1 && $NF != "" {n++} END {print n + 0}' "$work/ros_run/loop_steps.csv")
    [ "$clips" -eq "$named" ] || fail "the in-process loop saved $clips clips; the ROS run's log names $named"
    ;;
  kill_master)
    took=$(/usr/bin/python3 -c "import time; print(round(time.time() - $killed_at, 1))")
    [ "$status" -eq 1 ] || fail "echoplan_planner exited $status, expected 1"
    grep -q "trial stopped: .*the ROS master at $ROS_MASTER_URI does not answer" "$work/planner.log" \
      || { fail "the planner's log does not name the master"; tail -5 "$work/planner.log"; }
    echo "planner stopped $took s after the kill: $(grep -o 'trial stopped: .*' "$work/planner.log")"
    ;;
  kill_observation)
    took=$(/usr/bin/python3 -c "import time; print(round(time.time() - $killed_at, 1))")
    [ "$status" -eq 1 ] || fail "echoplan_planner exited $status, expected 1"
    grep -q "trial stopped: .*/echoplan/observe" "$work/planner.log" \
      || { fail "the planner's log does not name the failed service"; cat "$work/planner.log"; }
    /usr/bin/python3 -c "import sys; sys.exit(0 if $took < 30 else 1)" || fail "the planner took $took s to give up"
    grep -q "went away and did not come back within 10 s" "$work/planner.log" \
      || fail "the planner's log does not say the service did not come back"
    [ "$(wc -l <"$work/ros_run/loop_steps.csv")" -ge 2 ] || fail "the steps finished before the kill were not kept"
    echo "planner stopped $took s after the kill: $(grep -o 'trial stopped: .*' "$work/planner.log")"
    ;;
  restart_observation | restart_listener)
    [ "$status" -eq 0 ] || { fail "echoplan_planner exited $status after the restart"; cat "$work/planner.log"; }
    ended=$(awk -F, 'NR > 1 && $3 ~ /^move_to_/ {n++} END {print n + 0}' "$work/ros_run/loop_steps.csv")
    [ "$ended" -eq "$trials" ] || fail "$ended of $trials trials ended in a sorting action"
    # The stand-in dies during its call: that step's fault is in the log, and the restarted node serves
    # the rest. A listener killed during a recording leaves a fault too; one killed between
    # recordings costs nothing but the wait.
    if [ "$case_name" = restart_observation ]; then
      fault="observation service failed"
      [ "$(grep -c "$fault" "$work/ros_run/loop_steps.jsonl")" -eq 1 ] \
        || fail "expected one step with the fault '$fault'"
      grep -q "heard" "$work/observation_again.log" || fail "the restarted observation node served nothing"
    else
      fault="recorder failed"
    fi
    echo "$(grep -c "$fault" "$work/ros_run/loop_steps.jsonl") step(s) with '$fault'; $ended trials sorted"
    ;;
  restart_master)
    [ "$status" -eq 0 ] || { fail "echoplan_planner exited $status after the master restarted"; cat "$work/planner.log"; }
    ended=$(awk -F, 'NR > 1 && $3 ~ /^move_to_/ {n++} END {print n + 0}' "$work/ros_run/loop_steps.csv")
    [ "$ended" -eq "$trials" ] || fail "$ended of $trials trials ended in a sorting action"
    skipped=$(grep -c '"observation_skipped":true' "$work/ros_run/loop_steps.jsonl")
    [ "$skipped" -le 1 ] || fail "$skipped observations skipped; the outage can cost one at most"
    # A planner started now looks every node up through the new master.
    start planner_after timeout 60 "$build/echoplan_planner" _problem:="$work/problem.yaml" _out:="$work/ros_run_after" \
      _seed:=$seed _episodes:=$episodes _trials:=1 _wait_timeout_s:=10
    wait "$started"
    after=$?
    [ "$after" -eq 0 ] || { fail "a planner started after the restart exited $after"; tail -5 "$work/planner_after.log"; }
    grep -q 'move_to_' "$work/ros_run_after/loop_steps.csv" 2>/dev/null \
      || fail "the trial of a planner started after the restart did not end in a sorting action"
    echo "the master was killed after step 1 and restarted; each node registered again:"
    for node in sim_robot listener observation planner; do
      echo "  echoplan_$node: $(grep -o 'registered [0-9]* topic.*again' "$work/$node.log" | head -1)"
    done
    echo "$skipped observation(s) skipped; $ended trials sorted"
    ;;
  retry_safe | fail_unsafe)
    [ "$status" -eq 0 ] || { fail "echoplan_planner exited $status"; cat "$work/planner.log"; }
    # The sorting step the stand-in failed: its attempts and its status.
    read -r attempts sort_status sort_fault < <(/usr/bin/python3 -c '
import json, sys
steps = [json.loads(line) for line in open(sys.argv[1])]
first = next(s for s in steps if s["action"].startswith("move_to_"))
fault = (first.get("fault") or {}).get("kind", "none").replace(" ", "_")
print(first["report"]["attempts"], first["report"]["status"], fault)' "$work/ros_run/loop_steps.jsonl")
    ended=$(awk -F, 'NR > 1 && $3 ~ /^move_to_/ && $4 == "done" {n++} END {print n + 0}' "$work/ros_run/loop_steps.csv")
    if [ "$case_name" = retry_safe ]; then
      [ "$attempts $sort_status" = "2 done" ] || fail "the first sorting action took $attempts attempt(s), $sort_status; expected 2, done"
      [ "$ended" -eq "$trials" ] || fail "$ended of $trials trials sorted"
    else
      [ "$attempts $sort_status" = "1 failed" ] || fail "the first sorting action took $attempts attempt(s), $sort_status; expected 1, failed"
      [ "$ended" -eq $((trials - 1)) ] || fail "$ended of $trials trials sorted; expected all but the failed one"
      grep -q -- "-> action failed: the gripper missed" "$work/planner.log" || fail "the planner's log does not say the action failed"
      # A sort that failed put the object nowhere: a fault that ends the trial, not a sorted object.
      [ "$sort_fault" = action_failed ] || fail "the failed sort's fault is '$sort_fault', not 'action failed'"
    fi
    echo "first sorting action: $attempts attempt(s), $sort_status; $ended of $trials trials sorted"
    ;;
  *) fail "unknown case $case_name" ;;
esac

if [ "$failures" -eq 0 ]; then
  echo "ros_$case_name: all checks passed"
else
  for log in "$work"/*.log; do echo "--- $(basename "$log")"; tail -20 "$log"; done
fi
exit "$failures"
