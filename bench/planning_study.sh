#!/bin/sh
# The planning study of docs/BENCHMARKS.md ("Planning"): mean discounted reward (± 95% CI) of ABT and
# POMCP on the report's problem at episode and wall-time budgets, the same on generated 16- and
# 64-object problems, and Tiger. Trials run one after another (the machine is shared: never in
# parallel). Progress goes to stderr; the table goes to OUT/study.md.
#
#   bench/planning_study.sh [BUILD_DIR=build] [OUT=results/planning_study] [TRIALS=200]
set -eu
build=${1:-build}
out=${2:-results/planning_study}
trials=${3:-200}
bin=$build/echoplan
mkdir -p "$out"
table=$out/study.md

# run NAME PROBLEM SOLVER BUDGET_FLAGS...: one trials run into OUT/NAME, one row of the table.
run() {
  name=$1; problem=$2; solver=$3; shift 3
  echo "[$(date +%H:%M:%S)] $name: $solver $* on $problem" >&2
  "$bin" trials --problem "$problem" --solver "$solver" --seed 1 --out "$out/$name" "$@" \
    >"$out/$name.txt" 2>"$out/$name.log"
  python3 - "$out/$name" "$name" "$solver" "$*" >>"$table" <<'PY'
import csv, json, sys
folder, name, solver, flags = sys.argv[1:5]
s = json.load(open(folder + "/summary.json"))
budget = s["run"]["budget"]
# Episodes per second from the wall-time budgets: the episodes each step's search ran.
rate = ""
if "step_ms" in budget:
    episodes = [int(r["episodes"]) for r in csv.DictReader(open(folder + "/steps.csv"))]
    rate = "%.0f" % (sum(episodes) / len(episodes) / (budget["step_ms"] / 1000.0))
print("| %s | %s | %s | %d | %.3f ± %.3f | %.1f%% | %.2f | %s |" % (
    name, solver, flags, s["trials"], s["mean_discounted_reward"], s["ci95"],
    100 * s["accuracy"], s["mean_steps"], rate))
PY
}

header() {
  printf '\n### %s\n\n| run | solver | budget | trials | mean discounted reward ± 95%% CI | accuracy | mean steps | episodes/s |\n|---|---|---|---|---|---|---|---|\n' "$1" >>"$table"
}

echo "# Planning study ($(date -u +%Y-%m-%dT%H:%MZ), $trials trials per row on the report's problem)" >"$table"

header "problems/audio_objects.yaml (V*(b0) = 2.9534)"
for solver in abt pomcp; do
  for episodes in 100 1000 10000; do
    run "audio_${solver}_e$episodes" problems/audio_objects.yaml $solver --trials "$trials" --episodes $episodes
  done
  for ms in 5 20 100; do
    run "audio_${solver}_ms$ms" problems/audio_objects.yaml $solver --trials "$trials" --step-ms $ms
  done
done

# Scale: random object-identification problems with 4 sensing actions.
for objects in 16 64; do
  "$bin" make-problem --objects $objects --sensing-actions 4 --seed 1 -o "$out/objects_$objects.yaml"
  header "generated, $objects objects, 4 sensing actions (make-problem --seed 1)"
  for solver in abt pomcp; do
    run "obj${objects}_${solver}_e1000" "$out/objects_$objects.yaml" $solver --trials $((trials / 4)) --episodes 1000
    run "obj${objects}_${solver}_ms20" "$out/objects_$objects.yaml" $solver --trials $((trials / 4)) --step-ms 20
  done
done

# Tiger is infinite-horizon: 100 steps leave at most 0.95^100 * 19.4 = 0.11 of the value uncounted.
header "problems/tiger.pomdp (V*(uniform) = 19.371), 100 steps per trial"
for solver in abt pomcp; do
  run "tiger_${solver}_e1000" problems/tiger.pomdp $solver --trials $((trials / 2)) --episodes 1000 --max-steps 100
done
echo "done: $table" >&2
