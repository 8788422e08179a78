#!/bin/sh
# End-to-end checks of `echoplan make-problem` and `echoplan check`: a generated problem loads and is
# clean, the same seed writes the same file, another seed a different one, and bad input exits 2.
# Usage: make_problem_cli_test.sh ECHOPLAN_BINARY SOURCE_DIR
. "$(dirname "$0")/cli_test_lib.sh"

"$bin" make-problem --objects 16 --sensing-actions 4 --seed 7 -o "$work/a.yaml" >/dev/null || fail "make-problem"
"$bin" make-problem --objects 16 --sensing-actions 4 --seed 7 -o "$work/b.yaml" >/dev/null || fail "make-problem again"
"$bin" make-problem --objects 16 --sensing-actions 4 --seed 8 -o "$work/c.yaml" >/dev/null || fail "make-problem seed 8"
cmp -s "$work/a.yaml" "$work/b.yaml" || fail "same seed wrote different files"
cmp -s "$work/a.yaml" "$work/c.yaml" && fail "different seeds wrote the same file"
"$bin" check --problem "$work/a.yaml" | grep -q "ok: no problems found" || fail "generated problem not clean"
"$bin" check --problem "$src/problems/audio_objects.yaml" | grep -q "ok: no problems found" || fail "the report's problem"

# Bad input: exit status 2 and a message naming the file and line.
"$bin" make-problem --objects 1 --sensing-actions 4 --seed 1 -o "$work/x.yaml" 2>/dev/null
[ $? -eq 2 ] || fail "--objects 1 should exit 2"
sed 's/pringles_can: \[0.5, 0.3, 0.15, 0.05\]/pringles_can: [0.5, 0.3, 0.15, 0.06]/' \
  "$src/problems/audio_objects.yaml" > "$work/bad.yaml"
expect_input_error "bad row" "bad.yaml:34: observation row (slide, pringles_can) sums to 1.01" \
  check --problem "$work/bad.yaml"
printf 'discount: 0.95\nstates: 2\n' > "$work/bad.pomdp"
"$bin" check --problem "$work/bad.pomdp" 2>/dev/null
[ $? -eq 2 ] || fail "incomplete .pomdp should exit 2"
head -c 3000 /dev/urandom > "$work/noise.yaml"
"$bin" check --problem "$work/noise.yaml" 2>/dev/null
[ $? -eq 2 ] || fail "random bytes should exit 2"
finish "make-problem and check CLI"
