#!/bin/sh
# Tables drawn at random (`random:N`, sim/random_tables.h) end to end: synth-recordings spreads a
# recordings set over N drawn tables named in its manifest, the same from the same seed and others
# from another; a campaign draws its world's tables and its training set's apart (world_random_i,
# training_random_i), recording i of each pair on table i; a malformed count exits 2 naming the
# entry, and in a campaign its line. Usage: tables_cli_test.sh ECHOPLAN_BINARY SOURCE_DIR
. "$(dirname "$0")/cli_test_lib.sh"

# surface column of a manifest, one value per line.
surfaces() { awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == "surface") c = i; next } { print $c }' "$1"; }

synth() { "$bin" synth-recordings --per-pair 3 --objects paper_base --actions strike --surface random:3 "$@"; }
synth --seed 3 -o "$work/a" >/dev/null 2>&1 || fail "synth-recordings on random:3 exited $?"
[ "$(surfaces "$work/a/manifest.csv" | tr '\n' ' ')" = "random_1 random_2 random_3 " ] \
  || fail "the manifest does not name random_1..3 in order: $(surfaces "$work/a/manifest.csv" | tr '\n' ' ')"
synth --seed 3 -o "$work/b" >/dev/null 2>&1 || fail "the second synth-recordings exited $?"
cmp -s "$work/a/paper_base/strike/001.wav" "$work/b/paper_base/strike/001.wav" \
  || fail "the same seed did not give the same recording on random_2"
synth --seed 4 -o "$work/c" >/dev/null 2>&1 || fail "synth-recordings with another seed exited $?"
cmp -s "$work/a/paper_base/strike/001.wav" "$work/c/paper_base/strike/001.wav" \
  && fail "another seed gave the same recording"
expect_input_error "a count of 0" "'random:0': random tables are written random:N" \
  synth-recordings --per-pair 1 --objects paper_base --surface random:0 -o "$work/x"
[ -e "$work/x" ] && fail "a refused count still wrote $work/x"

campaign() {
  cat >"$work/campaign.yaml" <<YAML
seed: 2
arms:
  - {name: tables, problem: $src/problems/audio_objects.yaml, calibrate: true, trained_on_surfaces: true}
world:
  type: simulated
  problem: $src/problems/audio_objects.yaml
  surface: [random:2]
training_set:
  recordings_per_pair: 3
  surfaces: [$1]
trials:
  - {object: coffee_mug, trials: 2}
  - {object: paper_base, trials: 2}
planner: {solver: abt, episodes: 300, max_steps: 10}
YAML
}
campaign random:3
"$bin" experiment --config "$work/campaign.yaml" --out "$work/run" >/dev/null 2>"$work/run.err" \
  || { fail "the campaign exited $?"; cat "$work/run.err"; }
training=$work/run/training/recordings_on_surfaces/manifest.csv
[ "$(surfaces "$training" | sort | uniq -c | awk '{print $1 $2}' | tr '\n' ' ')" = \
  "8training_random_1 8training_random_2 8training_random_3 " ] \
  || fail "the training set is not 8 recordings on each of training_random_1..3: $(surfaces "$training" | sort | uniq -c)"
heard=$(grep -o '"surface":"[a-z_0-9]*"' "$work/run/journal.jsonl" | sort -u | tr '\n' ' ')
[ "$heard" = '"surface":"world_random_1" "surface":"world_random_2" ' ] \
  || fail "the trials did not stand on world_random_1 and world_random_2: $heard"
campaign random:many
expect_input_error "a campaign's malformed count" "campaign.yaml:10: 'random:many'" \
  experiment --config "$work/campaign.yaml" --out "$work/bad"
finish "random tables"
