#!/bin/sh
# The planner against the fixed strategies under its own model (docs/BENCHMARKS.md, "Under its own
# model"): the recorded-data stand-in of bench/dataset_campaign.sh SET=recorded (100 objects in 20
# groups, 9 behaviours, two performances per session, a tenth of the objects like another group),
# its problem for novel objects written by `echoplan train --hold-out object --problem-out`, then
# `echoplan trials` on that problem (the model as the world, an exact belief) with ABT at EPISODES
# episodes, information_gain, all_actions and best_single, TRIALS trials each on one seed. Prints
# each solver's accuracy (the object named) and share sorted right, drawn reward, expected reward
# (each reward's expectation under the belief: the same mean, less variance) and behaviours, and
# each strategy's paired expected-reward difference from ABT. What it shows: whether the planner
# makes the most of the model it is given. What it does not: anything about the data
# (bench/dataset_campaign.sh replays the sessions).
# With PROBLEM=FILE (environment): that problem instead of the stand-in, its one-line particle
# belief made exact (problems/audio_objects.yaml: four objects in two bins, where the sort is
# coarser than the object). With SOLVERS="abt ..." (environment): those solvers, abt first; when
# both greedy rules are among them, also decision_region's paired difference from information_gain.
# With ABT_FLAGS="..." (environment): more flags for ABT's run (e.g. "--leaf exact").
# Usage: bench/model_world.sh BUILD_DIR [TRIALS] [EPISODES] [OUT]
set -eu
build=$1
trials=${2:-200}
episodes=${3:-2000}
dir=$(mktemp -d)
out=${4:-$dir/model_world}
trap 'rm -rf "$dir"' EXIT
solvers=${SOLVERS:-abt information_gain all_actions best_single}
mkdir -p "$out"
if [ -n "${PROBLEM:-}" ]; then
  sed 's/^belief: {type: particle, particles: [0-9]*}/belief:\n  type: exact/' "$PROBLEM" >"$out/problem.yaml"
else
  "$build/bench/make_feature_set" -o "$dir/fs100" --objects 100 --group-size 5 --sessions 5 \
    --actions press,grasp,lift,drop,poke,push,shake,tap,squeeze \
    --action-scales 0.3,0.4,0.5,0.6,0.7,0.8,0.9,1.0,1.2 --modality audio:8:1.5 \
    --modality haptic:4:1.0 --group-separation 1.0 --seed 1 --repeats 2 --session-sd 0.6 \
    --lookalike-share 0.1 >/dev/null
  "$build/echoplan" train --data "$dir/fs100" --groups "$dir/fs100/groups.csv" --hold-out object \
    --problem-out "$out/problem.yaml" >/dev/null 2>&1
fi
# The problem's planner section is ABT's; its exact belief is what makes the expected reward exact.
grep -q "^  type: exact" "$out/problem.yaml" || { echo "model_world.sh: the problem's belief is not exact" >&2; exit 1; }
for solver in $solvers; do
  /usr/bin/time -f "%e" -o "$out/$solver.time" "$build/echoplan" trials --problem "$out/problem.yaml" \
    --solver "$solver" --trials "$trials" --episodes "$episodes" --seed 1 --out "$out/$solver" \
    $([ "$solver" = abt ] && echo "${ABT_FLAGS:-}") >/dev/null 2>&1
done
/usr/bin/python3 - "$out" $solvers <<'PY'
import csv, json, math, os, re, sys
from scipy.stats import t as student
out = sys.argv[1]
solvers = sys.argv[2:]
# Behaviours: every action but the sorting ones (the problem's `sorting: [...]` line).
sorting = re.search(r"^  sorting: \[(.*)\]", open(os.path.join(out, "problem.yaml")).read(), re.M)
sorting = set(sorting.group(1).split(", "))
def ci(values):
    n = len(values); m = sum(values) / n
    sd = math.sqrt(sum((v - m) ** 2 for v in values) / (n - 1))
    return m, student.ppf(0.975, n - 1) * sd / math.sqrt(n)
def expected(s):
    return [float(r["expected_reward"]) for r in csv.DictReader(open(os.path.join(out, s, "expected_rewards.csv")))]
print("| solver | accuracy, sorted right | drawn reward (95% CI) | expected reward (95% CI) | behaviours | expected minus abt, paired (95% CI) | wall s |")
print("|---|---|---|---|---|---|---|")
base = expected("abt")
for s in solvers:
    j = json.load(open(os.path.join(out, s, "summary.json")))
    e = j["expected_discounted_reward"]
    sensing = sum(v for k, v in j["mean_action_counts"].items() if k not in sorting)
    diff = "" if s == "abt" else "%+.2f ± %.2f" % ci([x - y for x, y in zip(expected(s), base)])
    wall = open(os.path.join(out, s + ".time")).read().split()[-1]
    right = j.get("sorted_right", j["accuracy"])
    print(f"| {s} | {100 * j['accuracy']:.0f}%, {100 * right:.0f}% | {j['mean_discounted_reward']:.2f} ± {j['ci95']:.2f} | "
          f"{e['mean']:.2f} ± {e['ci95']:.2f} | {sensing:.2f} | {diff} | {wall} |")
if "information_gain" in solvers and "decision_region" in solvers:
    d = ci([x - y for x, y in zip(expected("decision_region"), expected("information_gain"))])
    print("decision_region minus information_gain, expected reward, paired: %+.2f ± %.2f" % d)
PY
