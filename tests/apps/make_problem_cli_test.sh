#!/bin/sh
# End-to-end checks of `echoplan make-problem` and `echoplan check`: a generated problem loads and is
# clean, the same seed writes the same file, another seed a different one, and bad input exits 2.
# Usage: make_problem_cli_test.sh ECHOPLAN_BINARY SOURCE_DIR
set -u
bin=$1
src=$2
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

"$bin" make-problem --objects 16 --sensing-actions 4 --seed 7 -o "$dir/a.yaml" >/dev/null || fail "make-problem"
"$bin" make-problem --objects 16 --sensing-actions 4 --seed 7 -o "$dir/b.yaml" >/dev/null || fail "make-problem again"
"$bin" make-problem --objects 16 --sensing-actions 4 --seed 8 -o "$dir/c.yaml" >/dev/null || fail "make-problem seed 8"
cmp -s "$dir/a.yaml" "$dir/b.yaml" || fail "same seed wrote different files"
cmp -s "$dir/a.yaml" "$dir/c.yaml" && fail "different seeds wrote the same file"
"$bin" check --problem "$dir/a.yaml" | grep -q "ok: no problems found" || fail "generated problem not clean"
"$bin" check --problem "$src/problems/audio_objects.yaml" | grep -q "ok: no problems found" || fail "seed problem"

# Bad input: exit status 2 and a message naming the file and line.
"$bin" make-problem --objects 1 --sensing-actions 4 --seed 1 -o "$dir/x.yaml" 2>/dev/null
[ $? -eq 2 ] || fail "--objects 1 should exit 2"
sed 's/pringles_can: \[0.5, 0.3, 0.15, 0.05\]/pringles_can: [0.5, 0.3, 0.15, 0.06]/' \
  "$src/problems/audio_objects.yaml" > "$dir/bad.yaml"
msg=$("$bin" check --problem "$dir/bad.yaml" 2>&1)
[ $? -eq 2 ] || fail "bad row should exit 2"
echo "$msg" | grep -q "bad.yaml:34: observation row (slide, pringles_can) sums to 1.01" || fail "message: $msg"
printf 'discount: 0.95\nstates: 2\n' > "$dir/bad.pomdp"
"$bin" check --problem "$dir/bad.pomdp" 2>/dev/null
[ $? -eq 2 ] || fail "incomplete .pomdp should exit 2"
head -c 3000 /dev/urandom > "$dir/noise.yaml"
"$bin" check --problem "$dir/noise.yaml" 2>/dev/null
[ $? -eq 2 ] || fail "random bytes should exit 2"
echo "cli ok"
