#!/bin/sh
# End-to-end checks of `echoplan solve`: Tiger's bounds as JSON bracket its known value 19.371, the
# report's problem's YAML and .pomdp files solve and start with a strike, --out writes a policy, and bad
# input exits 2 with a message naming the file (or the option).
# Usage: solve_cli_test.sh ECHOPLAN_BINARY SOURCE_DIR
. "$(dirname "$0")/cli_test_lib.sh"

json=$("$bin" solve --problem "$src/problems/tiger.pomdp" --json --epsilon 2e-5 2>/dev/null) || fail "solve tiger"
echo "$json" | grep -q '^{"lower":' || fail "JSON must start with lower: $json"
# lower <= 19.3715 and upper >= 19.3705 (19.371 is rounded to 3 decimals), gap <= 1e-3.
echo "$json" | awk -F'[:,]' '{ l = $2; u = $4; exit !(l <= 19.3715 && u >= 19.3705 && u - l <= 1e-3) }' \
  || fail "tiger bounds: $json"

for f in audio_objects.yaml audio_objects.pomdp; do
  out=$("$bin" solve --problem "$src/problems/$f" --time-limit 1 --out "$work/$f" 2>/dev/null) || fail "solve $f"
  echo "$out" | grep -q "first action: strike" || fail "$f first action: $out"
  grep -q '"format": "echoplan-alpha-vectors"' "$work/$f/policy.json" || fail "$f policy.json"
done

# An on/off option of the exact solver: `bound_after_one PROBLEM OPTION VALUE FIELD` prints the
# bound FIELD (lower or upper) of V*(b0) after one expansion with OPTION set to VALUE.
bound_after_one() {
  field='\1'
  [ "$4" = upper ] && field='\2'
  "$bin" solve --problem "$1" --method exact --max-expansions 1 "$2" "$3" --json 2>/dev/null \
    | sed "s/^{\"method\":\"exact\",\"lower\":\([^,]*\),\"upper\":\([^,]*\),.*/$field/"
}
# `check_switch PROBLEM OPTION FIELD CHANGE`: the FIELD with OPTION on must beat off by more than 1
# in the direction CHANGE (raise or lower), and any other value than on/off exits 2 naming it.
check_switch() {
  on=$(bound_after_one "$1" "$2" on "$3") || fail "solve $1 $2 on"
  off=$(bound_after_one "$1" "$2" off "$3") || fail "solve $1 $2 off"
  awk -v on="$on" -v off="$off" -v change="$4" \
    'BEGIN { exit !(change == "raise" ? on > off + 1 : on < off - 1) }' \
    || fail "$2 on should $4 the $3 bound after one expansion: on $on, off $off"
  err=$("$bin" solve --problem "$1" "$2" maybe 2>&1 >/dev/null)
  [ $? -eq 2 ] || fail "$2 maybe should exit 2"
  echo "$err" | grep -q -- "$2" || fail "the error should name $2: $err"
}

# --sense-once: with prerequisites (grasp_first.yaml), one expansion bounds V* below by sensing once
# then sorting (on, the default) far above committing now (off).
check_switch "$src/problems/grasp_first.yaml" --sense-once lower raise

# --readings-left: with one slide and two strikes allowed (the report's problem), one expansion
# bounds V* above by what all three readings at once could earn (on, the default), far below one
# more sensing and the pair relaxation (off).
sed 's/^  sorting: \[move_to_A, move_to_B\]$/&\n  uses: {slide: 1, strike: 2}/' \
  "$src/problems/audio_objects.yaml" > "$work/limited.yaml"
grep -q "uses: {slide: 1, strike: 2}" "$work/limited.yaml" || fail "limited.yaml has no uses"
check_switch "$work/limited.yaml" --readings-left upper lower

"$bin" solve --problem "$work/missing.pomdp" 2>/dev/null
[ $? -eq 2 ] || fail "missing file should exit 2"
printf 'discount: 0.95\nstates: 2\n' > "$work/bad.pomdp"
expect_input_error "incomplete .pomdp" "bad.pomdp" solve --problem "$work/bad.pomdp"
"$bin" solve --problem "$src/problems/tiger.pomdp" --epsilon -1 2>/dev/null
[ $? -eq 2 ] || fail "negative epsilon should exit 2"
"$bin" solve --problem "$src/problems/tiger.pomdp" --time-limit 0 2>/dev/null
[ $? -eq 2 ] || fail "zero time limit should exit 2"
# --expand-within is a share of the gap: inside [0, 1] it solves, outside it is refused by name.
out=$("$bin" solve --problem "$src/problems/audio_objects.yaml" --method exact --expand-within 0.3 \
  --max-expansions 2000 2>/dev/null) || fail "solve with --expand-within 0.3"
echo "$out" | grep -q "first action: strike" || fail "--expand-within 0.3 first action: $out"
err=$("$bin" solve --problem "$src/problems/tiger.pomdp" --expand-within 1.5 2>&1 >/dev/null)
[ $? -eq 2 ] || fail "--expand-within 1.5 should exit 2"
echo "$err" | grep -q -- "--expand-within" || fail "the error should name --expand-within: $err"
finish "solve CLI"
