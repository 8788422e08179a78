#!/bin/sh
# `echoplan synth` and `echoplan dataset` end to end: run from a folder without objects/, they find the
# catalogue shipped with echoplan (common/data_dir.h); the same seed gives the same recording; unknown
# objects exit 2 naming the catalogue. Usage: synth_dataset_cli_test.sh ECHOPLAN_BINARY SOURCE_DIR
set -u
bin=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
cd "$work" || exit 1

"$bin" synth --object coffee_mug --action strike --seed 3 -o a.wav >/dev/null 2>err \
  || fail "synth from a folder without objects/ exited $?: $(cat err)"
"$bin" synth --object coffee_mug --action strike --seed 3 -o b.wav >/dev/null 2>&1 || fail "synth again"
cmp -s a.wav b.wav || fail "the same seed gave different recordings"
"$bin" synth --object coffee_mug --action strike --seed 3 --catalogue "$src/objects/catalogue.yaml" -o c.wav \
  >/dev/null 2>&1 || fail "synth with --catalogue"
cmp -s a.wav c.wav || fail "the shipped catalogue found by the binary is not the source tree's"

"$bin" synth --object teapot -o d.wav >/dev/null 2>err
status=$?
[ "$status" -eq 2 ] || fail "unknown object: exit status $status, expected 2"
grep -q "catalogue.yaml: unknown object 'teapot'" err || fail "unknown object: stderr lacks the message: $(cat err)"

"$bin" dataset --per-pair 1 --seed 1 --objects plastic_cup --actions strike -o set >/dev/null 2>err \
  || fail "dataset exited $?: $(cat err)"
[ -s set/plastic_cup/strike/000.wav ] || fail "dataset wrote no set/plastic_cup/strike/000.wav"
[ "$(wc -l <set/manifest.csv)" -eq 2 ] || fail "manifest.csv should hold a header and 1 row"

[ "$failures" -eq 0 ] && echo "all synth and dataset CLI checks passed"
exit "$failures"
