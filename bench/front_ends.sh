#!/bin/sh
# Two audio front ends through background noise (docs/BENCHMARKS.md, "Background noise"): the
# level-normalised summary (`summary-lda`, the default) against per-channel energy normalisation
# (`pcen-lda`), each trained on the main job's four objects in the lab's quiet and trained also in
# noise (add-noise --keep-quiet: letters and other prompts of the speaker, white and motor noise,
# -6 to 24 dB), then evaluated on held-out recordings (another seed) mixed with speech the
# training never played (the digits) and the room's noise at each LEVEL. Prints each preset's
# held-out accuracy per action and level: how much of the sound each front end keeps through noise,
# before any planning.
# Usage: bench/front_ends.sh BUILD_DIR [LEVELS] [PER_PAIR] [OUT]
set -eu
build=$1
levels=${2:-"24 12 6 0 -6"}
per_pair=${3:-10}
out=${4:-$(mktemp -d)}
bin="$build/echoplan"
speech=/usr/share/asterisk/sounds/en_US_f_Allison  # scripts/setup.sh installs it
objects=pringles_can,coffee_mug,plastic_cup,paper_base
mkdir -p "$out"
"$bin" synth-recordings --per-pair "$per_pair" --seed 1 --objects $objects -o "$out/train" >/dev/null 2>&1
"$bin" synth-recordings --per-pair "$per_pair" --seed 2 --objects $objects -o "$out/test" >/dev/null 2>&1
"$bin" add-noise --data "$out/train" --keep-quiet --ebr=-6:24 --seed 3 -o "$out/train_noise" \
  --noise "$speech/letters" "$speech/phonetic" "$speech/dictate" "$speech/followme" white motor \
  >/dev/null 2>&1
for level in $levels; do
  "$bin" add-noise --data "$out/test" --noise "$speech/digits" room --ebr="$level" --seed 4 \
    -o "$out/test_$level" >/dev/null 2>&1
done
# accuracy JSON: "action accuracy, ..." from evaluate --json.
accuracy() {
  python3 -c 'import json,sys; d=json.load(sys.stdin)["actions"]; print(", ".join("%s %.3f" % (a, v["accuracy"]) for a, v in d.items()))'
}
for preset in summary-lda pcen-lda; do
  for training in train train_noise; do
    "$bin" train --data "$out/$training" --classifier "$preset" --out "$out/$preset-$training.json" \
      >/dev/null 2>&1
    for level in quiet $levels; do
      data="$out/test_$level"
      [ "$level" = quiet ] && data="$out/test"
      printf '%s %s %s dB: ' "$preset" "$training" "$level"
      "$bin" evaluate --model "$out/$preset-$training.json" --data "$data" --json 2>/dev/null | accuracy
    done
  done
done
