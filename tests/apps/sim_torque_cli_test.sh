#!/bin/sh
# The simulated world heard through the arm's sensors: a model trained on simulated joint torques
# and wrist forces alone (`synth-recordings --signals effort,force`, no audio) is what `echoplan
# run` hears the simulated robot with, its rows computed from the physics of each action
# (robot/simulated_sensor_service.h). Checked: every object is sorted right on torque alone; the same
# trial with the mug's and the cup's recordings swapped in training believes the other object (so
# the decisions come from the torques); a model of sensor rows the arm does not measure is refused.
# Usage: sim_torque_cli_test.sh ECHOPLAN_BINARY SOURCE_DIR
. "$(dirname "$0")/cli_test_lib.sh"

"$bin" synth-recordings --per-pair 8 --seed 1 --signals effort,force -o "$work/tree" >"$work/synth.out" 2>&1 \
  || { fail "synth-recordings exited $?"; cat "$work/synth.out"; }
[ ! -e "$work/tree/coffee_mug/slide/000.wav" ] || fail "a WAV was written without audio"
train() {  # train TREE NAME
  "$bin" train --data "$1" --series effort=ur5-effort --series force=ur5-force \
    --problem-base "$src/problems/audio_objects.yaml" --out "$work/$2.json" --problem-out "$work/$2.yaml" \
    >"$work/$2.out" 2>&1 || { fail "train $2 exited $?"; cat "$work/$2.out"; }
}
train "$work/tree" torque
for object in coffee_mug plastic_cup pringles_can paper_base; do
  "$bin" run --object $object --model "$work/torque.json" --problem "$work/torque.yaml" --seed 3 \
    --episodes 500 --out "$work/run_$object" >"$work/run_$object.out" 2>&1 \
    || { fail "run $object exited $?"; cat "$work/run_$object.out"; continue; }
  grep -q "^result: $object sorted by move_to_[AB] (believed $object)" "$work/run_$object.out" \
    || fail "$object not sorted on torque alone: $(grep '^result' "$work/run_$object.out")"
  grep -q '"heard":{' "$work/run_$object/loop_steps.jsonl" || fail "$object: nothing was heard"
done

# The mug's and the cup's recordings swapped: the mug is now heard as the cup.
mkdir -p "$work/swapped"
cp -r "$work/tree/." "$work/swapped/"
mv "$work/swapped/coffee_mug" "$work/swapped/x" && mv "$work/swapped/plastic_cup" "$work/swapped/coffee_mug" \
  && mv "$work/swapped/x" "$work/swapped/plastic_cup"
python3 - "$work/swapped/manifest.csv" <<'PY' || fail "swapping the manifest's mug and cup"
import csv, sys
swap = {"coffee_mug": "plastic_cup", "plastic_cup": "coffee_mug"}
rows = list(csv.reader(open(sys.argv[1])))
for r in rows[1:]:
    if r[1] in swap:  # the mug's files, moved to the cup's folder, are the cup's now
        r[1] = swap[r[1]]
        r[0] = r[1] + r[0][r[0].index("/"):]
csv.writer(open(sys.argv[1], "w", newline=""), lineterminator="\n").writerows(rows)
PY
train "$work/swapped" swapped
"$bin" run --object coffee_mug --model "$work/swapped.json" --problem "$work/swapped.yaml" --seed 3 \
  --episodes 500 --out "$work/run_swapped" >"$work/run_swapped.out" 2>&1 || fail "run swapped exited $?"
grep -q "(believed plastic_cup)" "$work/run_swapped.out" \
  || fail "with the recordings swapped the mug is not believed the cup: $(grep '^result' "$work/run_swapped.out")"

# A model of rows the simulated arm does not measure (the shipped feature set's haptic rows).
mkdir -p "$work/haptic"
for behaviour in "$src"/experiments/data/synthetic_objects/*/; do
  mkdir -p "$work/haptic/$(basename "$behaviour")"
  cp "$behaviour/haptic.csv" "$work/haptic/$(basename "$behaviour")/"
done
"$bin" train --data "$work/haptic" --out "$work/haptic.json" >"$work/haptic.out" 2>&1 \
  || { fail "train haptic exited $?"; cat "$work/haptic.out"; }
expect_input_error "sensor rows the simulated arm does not measure" "the simulated arm measures series of effort" \
  run --object coffee_mug --model "$work/haptic.json" --problem "$work/torque.yaml" --out "$work/run_haptic"
finish "sim-torque"
