#!/bin/sh
# Faults outside the robot, end to end (docs/real-robot.md, "Faults and what echoplan does"):
#   - the disk fills while the campaign's journal is written: exit 2 naming the trial, the journal
#     left holding whole lines only, and the same command again finishes the campaign with the files
#     of one uninterrupted run;
#   - the disk fills while `echoplan run` saves a clip: exit 2 naming the trial, the step and the file;
#   - SIGTERM mid-step: `run` and `experiment` stop after the step in progress and exit 130, and the
#     campaign resumes to the files of one uninterrupted run.
# A full disk is a file-size limit (prlimit --fsize, in bytes) with SIGXFSZ ignored, so a write that
# crosses it fails with EFBIG, stopping partway as on a full disk, without root or a mount.
# Usage: faults_cli_test.sh ECHOPLAN_BINARY SOURCE_DIR
. "$(dirname "$0")/cli_test_lib.sh"

# No training set: the journal is the first file to outgrow the limit below.
config=$work/campaign.yaml
small_campaign "$config" 0
# whole_lines FILE: the file is empty or ends with a newline (no torn last line).
whole_lines() {
  [ ! -s "$1" ] || [ "$(tail -c 1 "$1" | wc -l)" -eq 1 ]
}
# limited BYTES COMMAND...: runs COMMAND with every file it writes limited to BYTES.
limited() {
  bytes=$1
  shift
  (trap '' XFSZ; exec prlimit --fsize="$bytes" "$@")
}

"$bin" experiment --config "$config" --out "$work/whole" --workers 1 >/dev/null 2>"$work/whole.err" \
  || { fail "whole run exited $?"; cat "$work/whole.err"; }

# The disk fills in the middle of the fourth trial's journal line.
limit=$(head -n 3 "$work/whole/journal.jsonl" | wc -c)
limit=$((limit + 100))
limited "$limit" "$bin" experiment --config "$config" --out "$work/full" --workers 1 >/dev/null 2>"$work/full.err"
status=$?
[ "$status" -eq 2 ] || { fail "a full disk under the journal: exit status $status, expected 2"; cat "$work/full.err"; }
grep -q "journal.jsonl: trial 3 (hand_tuned, pringles_can) could not be journalled: writing failed: File too large" \
  "$work/full.err" || { fail "the message does not name the journal, the trial and the fault:"; cat "$work/full.err"; }
grep -q "the trials journalled before it are kept whole; free space and run the same command again" \
  "$work/full.err" || fail "the message does not say what is kept and what to do"
whole_lines "$work/full/journal.jsonl" || fail "the journal was left with a torn line"
[ "$(wc -l <"$work/full/journal.jsonl")" -eq 3 ] || fail "the journal does not hold the 3 trials before the fault"
"$bin" experiment --config "$config" --out "$work/full" >/dev/null 2>"$work/resumed.err" \
  || { fail "the run after the disk was freed exited $?"; cat "$work/resumed.err"; }
grep -q "3 of 12 trials already in" "$work/resumed.err" || fail "the resumed run does not say it skips 3 trials"
same_files "$work/whole" "$work/full" "full disk and resumed against one run"

# SIGTERM mid-trial: exit 130, the finished trials kept, then the same command again.
"$bin" experiment --config "$config" --out "$work/term" --workers 1 >/dev/null 2>"$work/term.err" &
pid=$!
wait_for_lines "$work/term/journal.jsonl" 1
kill -TERM "$pid"
wait "$pid"
status=$?
[ "$status" -eq 130 ] || fail "experiment: exit status $status after SIGTERM, expected 130"
whole_lines "$work/term/journal.jsonl" || fail "SIGTERM left a torn journal line"
"$bin" experiment --config "$config" --out "$work/term" >/dev/null 2>&1 || fail "run after SIGTERM exited $?"
same_files "$work/whole" "$work/term" "SIGTERM and resumed against one run"

# `echoplan run`: a model first (trained on 3 simulated recordings a pair), then a run whose clips do
# not fit on the disk.
quick="--train-per-pair 3 --episodes 300"
"$bin" run --object plastic_cup $quick --seed 2 --out "$work/trained" >/dev/null 2>"$work/trained.err" \
  || { fail "training run exited $?"; cat "$work/trained.err"; }
model=$work/trained/model.json
limited 20000 "$bin" run --object plastic_cup --model "$model" --episodes 300 --seed 2 --out "$work/clipfull" \
  >/dev/null 2>"$work/clipfull.err"
status=$?
[ "$status" -eq 2 ] || { fail "a full disk under a clip: exit status $status, expected 2"; cat "$work/clipfull.err"; }
grep -q "clips/000_00_.*\.wav: trial 0, step 1: the clip could not be saved (.*); is the disk full?" \
  "$work/clipfull.err" || { fail "the message does not name the clip, the trial and the step:"; cat "$work/clipfull.err"; }
whole_lines "$work/clipfull/loop_steps.csv" || fail "loop_steps.csv was left with a torn line"
[ -z "$(ls "$work/clipfull/clips")" ] || fail "a part-written clip was left in clips/"

# SIGTERM mid-step of `echoplan run` (each step plans for 1.5 s): exit 130, trial.json says the trial
# was interrupted, and every logged step is whole in both logs with its clip.
"$bin" run --object plastic_cup --model "$model" --step-ms 1500 --seed 2 --out "$work/runterm" \
  >/dev/null 2>"$work/runterm.err" &
pid=$!
wait_for_lines "$work/runterm/loop_steps.csv" 2
kill -TERM "$pid"
wait "$pid"
status=$?
[ "$status" -eq 130 ] || { fail "run: exit status $status after SIGTERM, expected 130"; cat "$work/runterm.err"; }
grep -q "stopping after the current step" "$work/runterm.err" || fail "run: stderr does not say it is stopping"
grep -q '"interrupted": true' "$work/runterm/trial.json" || fail "run: trial.json does not say it was interrupted"
rows=$(($(wc -l <"$work/runterm/loop_steps.csv") - 1))
[ "$rows" -ge 1 ] || fail "run: the step finished before SIGTERM was not kept"
[ "$rows" -eq "$(wc -l <"$work/runterm/loop_steps.jsonl")" ] || fail "run: CSV and JSONL hold different step counts"
whole_lines "$work/runterm/loop_steps.csv" || fail "run: SIGTERM left a torn loop_steps.csv line"
sensing=$(grep -c ',\(slide\|strike\),done,' "$work/runterm/loop_steps.csv")
[ "$sensing" -eq "$(ls "$work/runterm/clips" | wc -l)" ] || fail "run: one clip per logged sensing step expected"

finish "faults CLI"
