#!/bin/sh
# `echoplan trials` end to end: bad flags exit 2 with a message, and the same seed gives
# byte-identical output files. Usage: trials_cli_test.sh ECHOPLAN_BINARY SOURCE_DIR
. "$(dirname "$0")/cli_test_lib.sh"
problem=$src/problems/audio_objects.yaml

expect_input_error "missing problem file" "nope.yaml: cannot open" trials --problem "$work/nope.yaml" --out "$work/o"
expect_input_error "zero trials" "trials: must be a number greater than 0" trials --problem "$problem" --out "$work/o" --trials 0
expect_input_error "negative per-object" "per-object: must be a number greater than 0" trials --problem "$problem" --out "$work/o" --per-object -2
expect_input_error "negative episodes" "episodes: must be a number greater than 0, got -5" trials --problem "$problem" --out "$work/o" --episodes -5
expect_input_error "zero step time" "step-ms: must be a number greater than 0" trials --problem "$problem" --out "$work/o" --step-ms 0
expect_input_error "trials and per-object" "excludes" trials --problem "$problem" --out "$work/o" --trials 3 --per-object 2
expect_input_error "policy with an online solver" "policy is for --solver offline" trials --problem "$problem" --out "$work/o" --solver abt --policy x.json
expect_input_error "both budgets" "excludes" trials --problem "$problem" --out "$work/o" --episodes 5 --step-ms 3
expect_input_error "unknown solver" "solver 'foo' is not one of" trials --problem "$problem" --out "$work/o" --solver foo
expect_input_error "unknown leaf value" "leaf value 'random'" trials --problem "$problem" --out "$work/o" --leaf random
expect_input_error "zero max steps" "max-steps must be >= 1" trials --problem "$problem" --out "$work/o" --max-steps 0
expect_input_error "bad depth" "max depth must be >= 1" trials --problem "$problem" --out "$work/o" --depth 0
expect_input_error "missing --out" "out is required" trials --problem "$problem"
expect_input_error "not a number" "trials" trials --problem "$problem" --out "$work/o" --trials many

# Same seed, same files, byte for byte.
for run in a b; do
  "$bin" trials --problem "$problem" --trials 4 --episodes 300 --seed 5 --out "$work/$run" >/dev/null 2>&1 \
    || { echo "FAIL: trials run $run exited $?"; failures=$((failures + 1)); }
done
for file in trials.csv steps.csv summary.json; do
  cmp -s "$work/a/$file" "$work/b/$file" || { echo "FAIL: $file differs between runs"; failures=$((failures + 1)); }
done
[ "$(wc -l <"$work/a/trials.csv")" -eq 5 ] || { echo "FAIL: trials.csv should hold a header and 4 rows"; failures=$((failures + 1)); }

# certify reads the steps.csv that trials wrote and answers with the documented JSON fields.
"$bin" certify --problem "$problem" --steps "$work/a/steps.csv" --expansions 2000 --root-expansions 2000 --json >"$work/cert" 2>/dev/null \
  || { echo "FAIL: certify exited $?"; failures=$((failures + 1)); }
for key in vstar_lower vstar_upper regret_mean regret_ci95 '"trials":4' bound_gap_mean; do
  grep -q -- "$key" "$work/cert" || { echo "FAIL: certify --json lacks $key:"; cat "$work/cert"; failures=$((failures + 1)); }
done

# The expected reward: with an exact belief, each reward's expectation under the belief it was chosen
# from has the same mean as the rewards drawn (checked against them: a formula that took another
# action's rewards lands far outside) with far less spread; with a particle belief it is not reported.
sed 's/^belief: .*/belief: {type: exact}/' "$problem" >"$work/exact.yaml"
"$bin" trials --problem "$work/exact.yaml" --solver random --trials 2000 --seed 3 --out "$work/expected" >"$work/expected.txt" 2>/dev/null \
  || fail "random trials with an exact belief exited $?"
grep -q "^expected reward  " "$work/expected.txt" || fail "the summary printed no expected reward"
grep -q expected_discounted_reward "$work/a/summary.json" && fail "a particle belief's summary.json reports an expected reward"
[ -e "$work/a/expected_rewards.csv" ] && fail "a particle belief's run wrote expected_rewards.csv"
python3 - "$work/expected" <<'PY' || fail "expected reward: see above"
import csv, json, os, sys
s = json.load(open(os.path.join(sys.argv[1], "summary.json")))
e = s["expected_discounted_reward"]
rows = list(csv.DictReader(open(os.path.join(sys.argv[1], "expected_rewards.csv"))))
drawn, ci = s["mean_discounted_reward"], s["ci95"]
bad = 0
if e["trials"] != s["trials"]:
    print(f"expected reward over {e['trials']} trials of {s['trials']}"); bad += 1
if [int(r["trial"]) for r in rows] != list(range(s["trials"])):
    print("expected_rewards.csv should hold one row per trial, in order"); bad += 1
elif abs(sum(float(r["expected_reward"]) for r in rows) / len(rows) - e["mean"]) > 1e-9:
    print("expected_rewards.csv's mean is not summary.json's"); bad += 1
if abs(e["mean"] - drawn) > ci:
    print(f"expected reward {e['mean']:.3f} is outside the drawn rewards' {drawn:.3f} +- {ci:.3f}"); bad += 1
if not e["sd"] < 0.6 * s["sd_discounted_reward"]:
    print(f"expected reward's sd {e['sd']:.2f} is not well below the drawn rewards' {s['sd_discounted_reward']:.2f}"); bad += 1
sys.exit(bad)
PY

# Sorted right beside the identity's accuracy, on the problem whose unlike objects strike as the
# other kind (random sorts, so the two differ), checked against the bins its file gives (cups to
# A, tins to B) and the identities believed, from trials.csv. Tiger has no objects: no
# sorted_right.
"$bin" trials --problem "$src/problems/correlated_repeats.yaml" --solver random --trials 60 --seed 2 \
  --out "$work/bins" >"$work/bins.txt" 2>/dev/null || fail "trials on correlated_repeats exited $?"
grep -q "^sorted right  " "$work/bins.txt" || fail "the summary printed no sorted-right share"
python3 - "$work/bins" <<'PY' || fail "sorted right: see above"
import csv, json, os, sys
s = json.load(open(os.path.join(sys.argv[1], "summary.json")))
rows = list(csv.DictReader(open(os.path.join(sys.argv[1], "trials.csv"))))
bin_of = {"cup": "A", "ringing_cup": "A", "tin": "B", "thudding_tin": "B"}
right = sum(r["n_move_to_" + bin_of[r["true_state"]]] == "1" for r in rows) / len(rows)
named = sum(r["true_state"] == r["believed_state"] for r in rows) / len(rows)
bad = 0
if abs(s["sorted_right"] - right) > 1e-9:
    print(f"sorted_right {s['sorted_right']} is not the {right} trials.csv gives"); bad += 1
if abs(s["accuracy"] - named) > 1e-9:
    print(f"accuracy {s['accuracy']} is not the {named} trials.csv gives"); bad += 1
sys.exit(bad)
PY

# The offline policy as a solver: solve Tiger, then run it; a policy for another problem is refused.
"$bin" solve --problem "$src/problems/tiger.pomdp" --out "$work/tiger_policy" >/dev/null 2>&1 \
  || { echo "FAIL: solve tiger"; failures=$((failures + 1)); }
"$bin" trials --problem "$src/problems/tiger.pomdp" --solver offline --policy "$work/tiger_policy/policy.json" \
  --trials 3 --max-steps 10 --seed 1 --out "$work/offline" >/dev/null 2>&1 \
  || { echo "FAIL: offline trials on tiger"; failures=$((failures + 1)); }
grep -q sorted_right "$work/offline/summary.json" && fail "tiger's summary.json reports a sorted-right share"
[ "$(wc -l <"$work/offline/steps.csv")" -eq 31 ] || { echo "FAIL: 3 tiger trials of 10 steps should log 30 steps"; failures=$((failures + 1)); }
expect_input_error "policy of another problem" "the policy is for 2 states" trials --problem "$problem" --out "$work/o" \
  --solver offline --policy "$work/tiger_policy/policy.json"

finish "trials CLI"
