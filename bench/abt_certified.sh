#!/bin/sh
# Certified share of V* for ABT and POMCP on the report's problem (docs/BENCHMARKS.md
# "Certified share of V*"): for each planner and per-step budget (5, 20, 100 ms; 1,000 and 10,000
# episodes), `echoplan trials` logs the decisions and `echoplan certify` bounds their regret
# against the exact V*. Every run uses the same seed, so the trials share their true objects and
# random streams as far as the planners' choices allow (paired). Runs go one after another (the
# machine is shared). Progress goes to stderr; the table to OUT/certified.md.
#
#   bench/abt_certified.sh [BUILD_DIR=build] [OUT=results/abt_certified] [TRIALS=200] \
#                          [EXPANSIONS=20000] [DISCOUNTS="0.99 0.95"] [PLANNERS="abt pomcp"] \
#                          [BUDGETS="--step-ms=5 --step-ms=20 --step-ms=100 --episodes=1000 --episodes=10000"]
# EXPANSIONS is certify's per-belief refinement (--expansions): more tightens the certificate's
# bounds (its looseness is the last column) at the cost of time.
# A PLANNERS entry is a solver name, optionally followed by :LEAF and :EXTRA (one more flag), e.g.
# "abt abt:exact abt:exact:--exact-share=0.5 abt:exact-offline pomcp".
set -eu
build=${1:-build}
out=${2:-results/abt_certified}
trials=${3:-200}
expansions=${4:-20000}
discounts=${5:-"0.99 0.95"}
planners=${6:-"abt pomcp"}
budgets=${7:-"--step-ms=5 --step-ms=20 --step-ms=100 --episodes=1000 --episodes=10000"}
bin=$build/echoplan
mkdir -p "$out"
table=$out/certified.md
printf '| planner | discount | budget | trials | episodes/step | regret ± 95%% CI | certified share of V* | regret, lower ends | V* bounds |\n|---|---|---|---|---|---|---|---|---|\n' >"$table"

for gamma in $discounts; do
  # The report's problem at this discount (the file's own is 0.99).
  problem=$out/audio_objects_$gamma.yaml
  sed "s/^discount: .*/discount: $gamma/" problems/audio_objects.yaml >"$problem"
  for entry in $planners; do
    planner=$(echo "$entry" | cut -d: -f1)
    leaf=$(echo "$entry:" | cut -d: -f2)
    extra=$(echo "$entry::" | cut -d: -f3)
    for budget in $budgets; do
      name=$(echo "${entry}_${gamma}_$budget" | tr -d '-' | tr '=:' '__')
      echo "[$(date +%H:%M:%S)] $name: trials" >&2
      # shellcheck disable=SC2086 # the leaf and extra flags are empty or one word each
      "$bin" trials --problem "$problem" --solver "$planner" ${leaf:+--leaf "$leaf"} $extra \
        --trials "$trials" --seed 1 "$budget" --out "$out/$name" >"$out/$name.txt" 2>"$out/$name.log"
      echo "[$(date +%H:%M:%S)] $name: certify" >&2
      "$bin" certify --problem "$problem" --steps "$out/$name/steps.csv" --json \
        --expansions "$expansions" >"$out/$name.certify.json" 2>>"$out/$name.log"
      python3 - "$out/$name" "$entry" "$gamma" "$budget" >>"$table" <<'PY'
import csv, json, sys
folder, planner, gamma, budget = sys.argv[1:5]
planner = planner.replace(":", " ")
c = json.load(open(folder + ".certify.json"))
episodes = [int(r["episodes"]) for r in csv.DictReader(open(folder + "/steps.csv"))]
vstar = 0.5 * (c["vstar_lower"] + c["vstar_upper"])
share = 1 - (c["regret_mean"] + c["regret_ci95"]) / vstar
print("| %s | %s | %s | %d | %.0f | %.3f ± %.3f | %.1f%% | %.3f | [%.3f, %.3f] |" % (
    planner, gamma, budget.lstrip("-").replace("=", " "), c["trials"],
    sum(episodes) / len(episodes), c["regret_mean"], c["regret_ci95"], 100 * share,
    c["regret_lower_mean"], c["vstar_lower"], c["vstar_upper"]))
PY
    done
  done
done
cat "$table"
