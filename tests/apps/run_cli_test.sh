#!/bin/sh
# `echoplan run` end to end: one trial through the whole loop with the simulated robot (training its
# own model when none is given), the same seed giving the same files, a trial replayed from a folder of
# recordings, a weighted variant standing in for its object, and each input error with exit status 2.
# Usage: run_cli_test.sh ECHOPLAN_BINARY SOURCE_DIR
. "$(dirname "$0")/cli_test_lib.sh"
# Small and fast: 3 training recordings per object and action, 300 search episodes per step.
quick="--train-per-pair 3 --episodes 300"

# check_trial DIR: a finished trial's files agree with each other and it ended by sorting.
check_trial() {
  dir=$1
  for f in loop_steps.csv loop_steps.jsonl trial.json; do [ -s "$dir/$f" ] || fail "$dir/$f missing"; done
  last=$(tail -n 1 "$dir/loop_steps.csv")
  case "$last" in
    *,move_to_A,done,*|*,move_to_B,done,*) ;;
    *) fail "$dir: the last step is not a sorting action: $last" ;;
  esac
  rows=$(($(wc -l <"$dir/loop_steps.csv") - 1))
  [ "$rows" -eq "$(wc -l <"$dir/loop_steps.jsonl")" ] || fail "$dir: CSV and JSONL hold different step counts"
  sensing=$(grep -c ',\(slide\|strike\),done,' "$dir/loop_steps.csv")
  [ "$sensing" -eq "$(ls "$dir/clips" | wc -l)" ] || fail "$dir: one clip per sensing step expected"
  grep -q "\"steps\": $rows" "$dir/trial.json" || fail "$dir: trial.json does not count $rows steps"
}

# A trial with the simulated robot and a model trained now on simulated recordings.
"$bin" run --object plastic_cup $quick --seed 2 --out "$work/a" >"$work/a.out" 2>"$work/a.err" \
  || { fail "run a exited $?"; cat "$work/a.err"; }
check_trial "$work/a"
for f in model.json problem.yaml; do [ -s "$work/a/$f" ] || fail "run a did not save $f"; done
grep -q "^step 1: " "$work/a.out" || fail "run a did not print its steps"
grep -q "plastic_cup .*█" "$work/a.out" || fail "run a did not print the belief as bars"
grep -q "^result: plastic_cup sorted by move_to_[AB] (believed " "$work/a.out" || { fail "run a: unexpected result"; cat "$work/a.out"; }

# The same seed, the same files.
"$bin" run --object plastic_cup $quick --seed 2 --out "$work/b" >/dev/null 2>&1 || fail "run b exited $?"
cmp -s "$work/a/loop_steps.csv" "$work/b/loop_steps.csv" || fail "loop_steps.csv differs between runs"
for clip in "$work/a/clips/"*; do
  cmp -s "$clip" "$work/b/clips/$(basename "$clip")" || fail "$(basename "$clip") differs between runs"
done

# Replay: recordings from a folder drive the loop; every clip heard is one of the true object's files.
"$bin" synth-recordings --per-pair 2 --seed 9 -o "$work/recordings" \
  --objects pringles_can,coffee_mug,plastic_cup,paper_base >/dev/null 2>&1 || fail "dataset exited $?"
"$bin" run --object coffee_mug --model "$work/a/model.json" --recordings "$work/recordings" \
  --episodes 300 --seed 4 --out "$work/c" >"$work/c.out" 2>"$work/c.err" || { fail "replay exited $?"; cat "$work/c.err"; }
check_trial "$work/c"
grep -q "replayed from" "$work/c.out" || fail "replay run does not say where its sound came from"
for clip in "$work/c/clips/"*; do
  action=$(basename "$clip" .wav | cut -d_ -f3)
  found=no
  for file in "$work/recordings/coffee_mug/$action/"*.wav; do cmp -s "$clip" "$file" && found=yes; done
  [ "$found" = yes ] || fail "replayed $(basename "$clip") is not a coffee_mug $action recording"
done

# A weighted variant stands in for its object: the truth is the mug, the world holds the heavy one.
"$bin" run --object coffee_mug_weighted --model "$work/a/model.json" --episodes 300 --seed 5 \
  --out "$work/d" >/dev/null 2>"$work/d.err" || { fail "variant run exited $?"; cat "$work/d.err"; }
grep -q '"object": "coffee_mug_weighted"' "$work/d/trial.json" || fail "variant: world object not logged"
grep -q '"true_state": "coffee_mug"' "$work/d/trial.json" || fail "variant: true state not the mug"

# Errors, each before any work.
expect_input_error "unknown object" "--object teapot: not an object of problem" run --object teapot --out "$work/e"
expect_input_error "replay without a model" "--recordings needs --model" run \
  --object coffee_mug --recordings "$work/recordings" --out "$work/e"
expect_input_error "missing recordings folder" "nowhere: the recordings folder does not exist" run \
  --object coffee_mug --model "$work/a/model.json" --recordings "$work/nowhere" --out "$work/e"
expect_input_error "recordings lacking the object" "no recordings of 'coffee_mug_weighted'" run \
  --object coffee_mug_weighted --model "$work/a/model.json" --recordings "$work/recordings" --out "$work/e"
expect_input_error "missing model file" "nope.json" run --object coffee_mug --model "$work/nope.json" --out "$work/e"
expect_input_error "tabular problem" "object-identification problem" run \
  --object coffee_mug --problem "$src/problems/tiger.pomdp" --model "$work/a/model.json" --out "$work/e"
expect_input_error "hand-tuned table with a rejecting model" "no 'unknown' observation symbol" run \
  --object coffee_mug --problem "$src/problems/audio_objects.yaml" --model "$work/a/model.json" --out "$work/e"
expect_input_error "too few training recordings" "train-per-pair must be at least 2" run \
  --object coffee_mug --train-per-pair 1 --out "$work/e"
touch "$work/file"
expect_input_error "unwritable output folder" "cannot create the output folder" run --object coffee_mug --out "$work/file/sub"
[ -e "$work/e" ] && [ -n "$(ls "$work/e")" ] && fail "an input error left files in the output folder"

finish "run CLI"
