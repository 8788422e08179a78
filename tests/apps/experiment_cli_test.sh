#!/bin/sh
# `echoplan experiment` and `echoplan merge` end to end on a small campaign: the same seed gives the
# same files; kill -9 or Ctrl-C in the middle and the same command again gives the files of one
# uninterrupted run; a one-core run equals a parallel one; merged shards equal the unsharded run; every
# bad input exits 2 with a message before any work. Usage: experiment_cli_test.sh ECHOPLAN_BINARY SOURCE_DIR
. "$(dirname "$0")/cli_test_lib.sh"

config=$work/campaign.yaml
small_campaign "$config"

# A whole run on all cores, and one on one core.
"$bin" experiment --config "$config" --out "$work/whole" >"$work/whole.out" 2>"$work/whole.err" \
  || { fail "whole run exited $?"; cat "$work/whole.err"; }
for file in trials.csv steps.csv summary.json summary.txt index.html journal.jsonl campaign.json \
  arms/hand_tuned/steps.csv figures/templates.png figures/templates.svg figures/confusion_hand_tuned.png \
  figures/belief_hand_tuned_coffee_mug_weighted.svg; do
  [ -s "$work/whole/$file" ] || fail "the whole run did not write $file"
done
[ "$(wc -l <"$work/whole/trials.csv")" -eq 13 ] || fail "trials.csv should hold a header and 12 rows"
grep -q "report: $work/whole/index.html" "$work/whole.out" || fail "stdout does not say where the report is"
grep -q "original objects" "$work/whole.out" || fail "the terminal summary lacks the original objects' row"
"$bin" experiment --config "$config" --out "$work/one_core" --workers 1 >/dev/null 2>&1 || fail "one-core run exited $?"
same_files "$work/whole" "$work/one_core" "one core against all cores"

# kill -9 after two trials are journalled, then the same command again.
"$bin" experiment --config "$config" --out "$work/killed" --workers 1 >/dev/null 2>&1 &
pid=$!
wait_for_lines "$work/killed/journal.jsonl" 2
kill -9 "$pid"
wait "$pid" 2>/dev/null
kept=$(wc -l <"$work/killed/journal.jsonl")
[ "$kept" -ge 2 ] && [ "$kept" -lt 12 ] || fail "after kill -9 the journal holds $kept trials (expected 2..11)"
"$bin" experiment --config "$config" --out "$work/killed" >"$work/resumed.out" 2>"$work/resumed.err" \
  || fail "resumed run exited $?"
grep -q "$kept of 12 trials already in" "$work/resumed.err" || fail "the resumed run does not say it skips $kept trials"
same_files "$work/whole" "$work/killed" "killed and resumed against one run"

# Ctrl-C: exit 130 with the finished trials kept, then the same command again.
# A shell starts background jobs with SIGINT ignored (and StopSignal keeps an ignored signal ignored):
# `env --default-signal=INT` gives the command the default disposition, as a terminal would.
env --default-signal=INT "$bin" experiment --config "$config" --out "$work/interrupted" --workers 1 >/dev/null 2>"$work/int.err" &
pid=$!
wait_for_lines "$work/interrupted/journal.jsonl" 1
kill -INT "$pid"
wait "$pid"
status=$?
[ "$status" -eq 130 ] || fail "exit status $status after SIGINT, expected 130"
[ -s "$work/interrupted/index.html" ] || fail "an interrupted run still writes its report"
"$bin" experiment --config "$config" --out "$work/interrupted" >/dev/null 2>&1 || fail "run after Ctrl-C exited $?"
same_files "$work/whole" "$work/interrupted" "interrupted and resumed against one run"

# Shards and merge.
"$bin" experiment --config "$config" --out "$work/shard1" --shard 1/2 >/dev/null 2>&1 || fail "shard 1/2 exited $?"
"$bin" experiment --config "$config" --out "$work/shard2" --shard 2/2 >/dev/null 2>&1 || fail "shard 2/2 exited $?"
[ "$(wc -l <"$work/shard1/journal.jsonl")" -eq 6 ] || fail "shard 1/2 should run 6 trials"
"$bin" merge --out "$work/merged" "$work/shard1" "$work/shard2" >/dev/null 2>"$work/merge.err" \
  || { fail "merge exited $?"; cat "$work/merge.err"; }
same_files "$work/whole" "$work/merged" "merged shards against the unsharded run"

# expect_refused DESCRIPTION MESSAGE ARGS...: an input error (cli_test_lib.sh) that neither trained nor ran.
expect_refused() {
  expect_input_error "$@"
  [ ! -e "$work/err_out/journal.jsonl" ] && [ ! -e "$work/err_out/training" ] || fail "$1: work started"
}
sed "s/object: plastic_cup/object: teapot, plays: plastic_cup/" "$config" >"$work/teapot.yaml"
expect_refused "object without catalogue entry" "object 'teapot' has no entry in the catalogue" \
  experiment --config "$work/teapot.yaml" --out "$work/err_out"
sed "s|training_set: {recordings_per_pair: 1}|training_set: {recordings: $work/no_recordings}|" "$config" >"$work/norec.yaml"
expect_refused "missing recordings folder" "no_recordings: the recordings folder does not exist" \
  experiment --config "$work/norec.yaml" --out "$work/err_out"
touch "$work/a_file"
expect_refused "unwritable output folder" "cannot create the output folder" \
  experiment --config "$config" --out "$work/a_file/out"
expect_refused "a folder of another campaign" "holds a different campaign" \
  experiment --config "$config" --out "$work/whole" --seed 99
expect_refused "bad shard" "must be I/N" experiment --config "$config" --out "$work/err_out" --shard 3/2
expect_refused "missing config" "cannot open the campaign file" \
  experiment --config "$work/nope.yaml" --out "$work/err_out"
sed 's/seed: 4/sed: 4/' "$config" >"$work/typo.yaml"
expect_refused "typo in the config" "typo.yaml:1: unknown key 'sed'" \
  experiment --config "$work/typo.yaml" --out "$work/err_out"
# A model trained for two of the four objects: the campaign that trains it stops with exit 2 (the
# calibrated arm needs all four), leaving the trained model; given as training_set.model it is refused
# before any work.
sed -e 's|training_set: {recordings_per_pair: 1}|training_set: {recordings_per_pair: 2, objects: [pringles_can, coffee_mug]}|' \
  -e 's|  - {name: hand_tuned, problem: \(.*\)}|  - {name: calibrated, problem: \1, calibrate: true}|' "$config" >"$work/two.yaml"
"$bin" experiment --config "$work/two.yaml" --out "$work/two" >/dev/null 2>"$work/two.err"
[ $? -eq 2 ] && grep -q "observation model was trained for" "$work/two.err" \
  || { fail "training for two objects should fail with exit 2 naming the model's objects"; cat "$work/two.err"; }
[ -s "$work/two/training/model.json" ] || fail "the two-object model was not kept"
sed -e "s|training_set: {recordings_per_pair: 1}|training_set: {model: $work/two/training/model.json}|" \
  -e 's|  - {name: hand_tuned, problem: \(.*\)}|  - {name: calibrated, problem: \1, calibrate: true}|' "$config" >"$work/given.yaml"
expect_refused "model trained for other objects" "observation model was trained for" \
  experiment --config "$work/given.yaml" --out "$work/err_out"

# A graded arm hearing a given model plays the trials it played with the model the campaign trained
# (the same file), in a simulated world: given models once failed the check of a graded arm's loops.
sed -e 's|training_set: {recordings_per_pair: 1}|training_set: {recordings_per_pair: 2}|' \
  -e 's|  - {name: hand_tuned, problem: \(.*\)}|  - {name: graded, problem: \1, calibrate: true, observations: graded}|' \
  -e 's|world: {type: model,|world: {type: simulated,|' -e 's|trials: 4}|trials: 1}|' \
  "$config" >"$work/graded.yaml"
"$bin" experiment --config "$work/graded.yaml" --out "$work/graded" >/dev/null 2>"$work/graded.err" \
  || { fail "graded campaign exited $?"; cat "$work/graded.err"; }
sed -e "s|training_set: {recordings_per_pair: 2}|training_set: {model: $work/graded/training/model.json}|" \
  "$work/graded.yaml" >"$work/graded_given.yaml"
"$bin" experiment --config "$work/graded_given.yaml" --out "$work/graded_given" >/dev/null 2>"$work/given.err" \
  || { fail "graded arm with a given model exited $?"; cat "$work/given.err"; }
cmp -s "$work/graded/trials.csv" "$work/graded_given/trials.csv" \
  && cmp -s "$work/graded/steps.csv" "$work/graded_given/steps.csv" \
  || fail "a graded arm hearing the given model played other trials than with the model trained"
grep -q "@high" "$work/graded_given/steps.csv" || fail "the given model's arm heard no graded symbol"

cp -r "$work/shard2" "$work/other"
sed -i 's/"seed": 4/"seed": 99/' "$work/other/campaign.json"
expect_refused "merging other campaigns" "holds another campaign" \
  merge --out "$work/err_merge" "$work/shard1" "$work/other"
[ ! -e "$work/err_merge" ] || fail "a refused merge created its folder"

# The shipped dataset-world example: every (object, session) a trial of five arms, paired; the session
# in trials.csv; the arms' figures; a resumed run writes the same files.
"$bin" experiment --config "$src/experiments/dataset_example.yaml" --out "$work/dataset" \
  >"$work/dataset.out" 2>"$work/dataset.err" || { fail "dataset example exited $?"; cat "$work/dataset.err"; }
[ "$(wc -l <"$work/dataset/trials.csv")" -eq 241 ] || fail "dataset trials.csv: a header and 5 x 48 rows"
head -1 "$work/dataset/trials.csv" | grep -q ",arm,object,session,seed$" || fail "dataset trials.csv lacks session and seed"
grep -q "^0,.*,plan,obj0,s0,[0-9][0-9]*$" "$work/dataset/trials.csv" || fail "dataset trial 0 is not obj0's session s0 with its seed"
for file in figures/accuracy_vs_actions.png figures/actions_chosen.svg index.html summary.json; do
  [ -s "$work/dataset/$file" ] || fail "the dataset run did not write $file"
done
grep -q "information_gain minus plan, paired" "$work/dataset.out" || fail "no paired difference printed"
"$bin" experiment --config "$src/experiments/dataset_example.yaml" --out "$work/dataset" \
  >"$work/dataset2.out" 2>&1 || fail "dataset example again exited $?"
grep -q "240 of 240 trials already" "$work/dataset2.out" || fail "the second dataset run redid trials"

finish "experiment CLI"
