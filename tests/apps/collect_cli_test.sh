#!/bin/sh
# `echoplan collect` on the simulated robot: two objects, sessions of a slide then a strike with the
# arm's torques and force; run again with more sessions it adds only the missing ones and leaves
# the rest byte for byte; the same seed gives the same files; the tree trains; bad input is refused.
# Usage: collect_cli_test.sh ECHOPLAN_BINARY SOURCE_DIR
. "$(dirname "$0")/cli_test_lib.sh"

collect() {
  "$bin" collect --objects coffee_mug,plastic_cup --seed 3 --signals effort,force "$@" >"$work/out" 2>"$work/err"
}
collect --sessions 2 -o "$work/tree" || { fail "collect exited $?"; cat "$work/err"; }
grep -q "^8 performances recorded, 0 already there" "$work/out" \
  || { fail "not 8 performances"; cat "$work/out"; }
[ "$(wc -l <"$work/tree/manifest.csv")" -eq 9 ] || fail "the manifest does not list 8 performances"
head -1 "$work/tree/manifest.csv" | grep -q "^file,object,action,session,status$" || fail "manifest header"
grep -q "^plastic_cup/strike/s002.wav,plastic_cup,strike,2,done$" "$work/tree/manifest.csv" \
  || { fail "plastic_cup's second strike is not listed"; cat "$work/tree/manifest.csv"; }
head -1 "$work/tree/coffee_mug/slide/s001.effort.csv" | grep -q "^t,j1,j2,j3,j4,j5,j6,j7$" || fail "effort header"
head -1 "$work/tree/coffee_mug/strike/s001.force.csv" | grep -q "^t,force_x,force_y,force_z$" || fail "force header"
cp "$work/tree/coffee_mug/strike/s002.wav" "$work/kept.wav"

collect --sessions 3 -o "$work/tree" || { fail "the resumed collect exited $?"; cat "$work/err"; }
grep -q "^4 performances recorded, 8 already there" "$work/out" || { fail "resume did not add only session 3"; cat "$work/out"; }
cmp -s "$work/kept.wav" "$work/tree/coffee_mug/strike/s002.wav" || fail "resuming rewrote a finished performance"
[ "$(wc -l <"$work/tree/manifest.csv")" -eq 13 ] || fail "the resumed manifest does not list 12 performances"

collect --sessions 3 -o "$work/again" || fail "the second collection exited $?"
for f in coffee_mug/slide/s003.wav plastic_cup/strike/s001.force.csv; do
  cmp -s "$work/tree/$f" "$work/again/$f" || fail "the same seed gave another $f"
done

"$bin" train --data "$work/tree" --hold-out session --out "$work/model.json" >"$work/train.out" 2>&1 \
  || { fail "train on the collected tree exited $?"; cat "$work/train.out"; }
grep -q "effort" "$work/train.out" || fail "train does not report the effort modality"

expect_input_error "an unknown object" "unknown object 'teapot'" collect --sessions 1 -o "$work/t2" --objects teapot
mkdir -p "$work/foreign" && printf 'file,object,action\n' >"$work/foreign/manifest.csv"
expect_input_error "a folder holding another tree" "not a collection's manifest" \
  collect --objects coffee_mug --sessions 1 -o "$work/foreign"
finish collect
