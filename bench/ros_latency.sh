#!/bin/bash
# Latency of the loop over ROS (docs/BENCHMARKS.md): the four nodes on a roscore on 127.0.0.1, TRIALS
# trials at EPISODES search episodes per step, then the same trials in process (the baseline: same
# parts without ROS). Prints the planner's median latencies (end of action -> belief updated, the
# observation call within it, recorder start = parameter set -> listener capturing) and the
# observation node's own classification time per request.
#
# Usage: bench/ros_latency.sh BUILD_DIR [sim|mic] [TRIALS] [EPISODES]
#   sim: the listener hears the simulated robot; mic: the listener records with PortAudio from a
#   capture device reading a file (ALSA file plugin, not paced in real time).
# LISTENER_ARGS (environment) adds private parameters to the listener, e.g. _cached_param:=true.
set -eu
build=$1
layout=${2:-sim}
trials=${3:-10}
episodes=${4:-300}
. "$(dirname "$0")/../tests/robot/ros/ros_session.sh"
ros_session_begin
"$build/tests/robot/ros/ros_loop_reference" prepare "$work"

source=simulation
min_duration=0
ref=sim
if [ "$layout" = mic ]; then
  source=microphone
  min_duration=0.1  # the file-backed device fills 0.5 s in a few ms; leave it time under load
  ref=mic
  file_microphone "$build/echoplan"
fi
start sim_robot "$build/echoplan_sim_robot" _min_duration_s:=$min_duration
start listener "$build/echoplan_listener" _source:=$source _max_seconds:=0.5 ${LISTENER_ARGS:-}
start observation "$build/echoplan_observation" _model:="$work/model.json"
"$build/echoplan_planner" _problem:="$work/problem.yaml" _out:="$work/ros_run" _seed:=1 _episodes:="$episodes" \
  _trials:="$trials" >"$work/planner.log" 2>&1
echo "over ROS ($layout layout, $trials trials):"
grep -o 'latency, .*ms' "$work/planner.log" | sed 's/^/  planner: /'
grep -o 'in [0-9.]* ms' "$work/observation.log" | awk '{print $2}' | sort -n |
  awk '{v[NR] = $1} END {m = NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2;
       printf "  observation node: classification median %.2f ms over %d requests\n", m, NR}'
"$build/tests/robot/ros/ros_loop_reference" run "$work" "$work/in_process" $ref 1 "$episodes" "$trials" 0.5 \
  >"$work/reference.log" 2>&1
echo "in process (baseline, same trials):"
grep -o 'latency, .*ms' "$work/reference.log" | sed 's/^/  /'
cmp -s "$work/ros_run/loop_steps.csv" "$work/in_process/loop_steps.csv" && echo "logs identical: yes" || echo "logs identical: NO"
