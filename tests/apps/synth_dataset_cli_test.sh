#!/bin/sh
# `echoplan synth` and `echoplan synth-recordings` end to end: run from a folder without objects/, they find the
# catalogue shipped with echoplan (common/data_dir.h); the same seed gives the same recording; unknown
# objects exit 2 naming the catalogue. Usage: synth_dataset_cli_test.sh ECHOPLAN_BINARY SOURCE_DIR
. "$(dirname "$0")/cli_test_lib.sh"
cd "$work" || exit 1

"$bin" synth --object coffee_mug --action strike --seed 3 -o a.wav >/dev/null 2>err \
  || fail "synth from a folder without objects/ exited $?: $(cat err)"
"$bin" synth --object coffee_mug --action strike --seed 3 -o b.wav >/dev/null 2>&1 || fail "synth again"
cmp -s a.wav b.wav || fail "the same seed gave different recordings"
"$bin" synth --object coffee_mug --action strike --seed 3 --catalogue "$src/objects/catalogue.yaml" -o c.wav \
  >/dev/null 2>&1 || fail "synth with --catalogue"
cmp -s a.wav c.wav || fail "the shipped catalogue found by the binary is not the source tree's"

expect_input_error "unknown object" "catalogue.yaml: unknown object 'teapot'" synth --object teapot -o d.wav

"$bin" synth-recordings --per-pair 1 --seed 1 --objects plastic_cup --actions strike -o set >/dev/null 2>err \
  || fail "synth-recordings exited $?: $(cat err)"
[ -s set/plastic_cup/strike/000.wav ] || fail "synth-recordings wrote no set/plastic_cup/strike/000.wav"
[ "$(wc -l <set/manifest.csv)" -eq 2 ] || fail "manifest.csv should hold a header and 1 row"
# The command's earlier name still works, and writes the same files.
"$bin" dataset --per-pair 1 --seed 1 --objects plastic_cup --actions strike -o old >/dev/null 2>err \
  || fail "dataset (the old name) exited $?: $(cat err)"
cmp -s set/plastic_cup/strike/000.wav old/plastic_cup/strike/000.wav || fail "dataset and synth-recordings differ"

finish "synth and synth-recordings CLI"
