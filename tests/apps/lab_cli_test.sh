#!/bin/sh
# The lab's measured world (experiments/chapter5_lab.yaml) end to end at a small budget: the shipped
# campaign with 2 trials per object and 1,000 episodes per decision completes, writes both arms (the
# report's hand-tuned table and the planner that knows the lab's) beside the report's numbers, and
# `echoplan certify` reads each arm's steps against the lab problem.
# Usage: lab_cli_test.sh ECHOPLAN_BINARY SOURCE_DIR
. "$(dirname "$0")/cli_test_lib.sh"

# The shipped campaign, made small, with its relative paths made absolute.
config=$work/chapter5_lab.yaml
sed -e "s|\.\./problems/|$src/problems/|g" \
    -e "s|^reference: chapter5_reference.yaml|reference: $src/experiments/chapter5_reference.yaml|" \
    -e "s|trials: 10}|trials: 2}|" \
    -e "s|episodes: 20000|episodes: 1000|" \
    "$src/experiments/chapter5_lab.yaml" >"$config"
[ "$(grep -c "trials: 2}" "$config")" -eq 4 ] || fail "the campaign no longer has four groups of 10 trials"
grep -q "episodes: 1000$" "$config" || fail "the campaign no longer plans with 20000 episodes"
grep -q "world: {type: model, problem: $src/problems/audio_objects_lab.yaml}" "$config" \
  || fail "the campaign's world is not the lab problem's table"
grep -q "reference: $src/experiments/chapter5_reference.yaml" "$config" || fail "the campaign names no reference"

"$bin" experiment --config "$config" --out "$work/lab" >"$work/lab.out" 2>"$work/lab.err" \
  || { fail "the lab campaign exited $?"; cat "$work/lab.err"; }
for file in trials.csv steps.csv summary.json summary.txt index.html \
  arms/hand_tuned/trials.csv arms/hand_tuned/steps.csv arms/lab/trials.csv arms/lab/steps.csv; do
  [ -s "$work/lab/$file" ] || fail "the lab campaign did not write $file"
done
[ "$(wc -l <"$work/lab/trials.csv")" -eq 17 ] || fail "trials.csv should hold a header and 16 rows (2 arms x 4 objects x 2)"
for arm in hand_tuned lab; do
  [ "$(wc -l <"$work/lab/arms/$arm/trials.csv")" -eq 9 ] || fail "arm $arm should have 8 trials"
done
grep -q "arm hand_tuned (plans with $src/problems/audio_objects.yaml)" "$work/lab.out" \
  || fail "the summary lacks the hand-tuned arm"
grep -q "arm lab (plans with $src/problems/audio_objects_lab.yaml)" "$work/lab.out" || fail "the summary lacks the lab arm"
grep -q "report: correct" "$work/lab.out" || fail "the summary lacks the report's columns"
[ ! -e "$work/lab/training/model.json" ] || fail "a model world with no calibrating arm trained a classifier"

# Each arm's decisions, certified under the lab's table (V*(b0) = 6.37).
for arm in hand_tuned lab; do
  "$bin" certify --problem "$src/problems/audio_objects_lab.yaml" --steps "$work/lab/arms/$arm/steps.csv" --json \
    >"$work/certify_$arm.json" 2>"$work/certify_$arm.err" || { fail "certify of arm $arm exited $?"; cat "$work/certify_$arm.err"; }
  grep -q '"vstar_lower":6\.37' "$work/certify_$arm.json" || fail "certify of arm $arm does not bound V*(b0) at 6.37"
  grep -q '"trials":8,' "$work/certify_$arm.json" || fail "certify of arm $arm did not read 8 trials"
done

finish lab
