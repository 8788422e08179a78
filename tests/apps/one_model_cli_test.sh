#!/bin/sh
# One observation model from recorded data to the loop: `train --data FEATURESET --out` writes a model
# of several modalities; a dataset campaign with that frozen model (world.model) and `echoplan run
# --data` on a session of it, with the campaign trial's seed and the arm's solver, take the same
# actions and hear the same observations at every step; a recordings tree with a groups file beside its
# object folders trains; a model whose classes are not the campaign's is refused.
# Usage: one_model_cli_test.sh ECHOPLAN_BINARY SOURCE_DIR
. "$(dirname "$0")/cli_test_lib.sh"
data="$src/experiments/data/synthetic_objects"

# Train on sessions s0-s2 of the shipped example (audio and haptic), hold s3 back.
python3 - "$data" "$work" <<'PY' || fail "splitting the feature set"
import csv, glob, os, shutil, sys
data, work = sys.argv[1], sys.argv[2]
for split, keep in (("train", lambda s: s != "s3"), ("test", lambda s: s == "s3")):
    for f in glob.glob(os.path.join(data, "*", "*.csv")):
        out = os.path.join(work, split, os.path.relpath(f, data))
        os.makedirs(os.path.dirname(out), exist_ok=True)
        rows = list(csv.reader(open(f)))
        with open(out, "w", newline="") as o:
            w = csv.writer(o)
            w.writerow(rows[0])
            w.writerows(r for r in rows[1:] if keep(r[1]))
shutil.copy(os.path.join(data, "groups.csv"), os.path.join(work, "train", "groups.csv"))
PY
"$bin" train --data "$work/train" --out "$work/model.json" --problem-out "$work/problem.yaml" \
  >"$work/train.out" 2>&1 || { fail "train exited $?"; cat "$work/train.out"; }
grep -q '"name":"audio"' "$work/model.json" || fail "the model lacks the audio modality"
grep -q '"name":"haptic"' "$work/model.json" || fail "the model lacks the haptic modality"
grep -q '"version":2' "$work/model.json" || fail "the model is not format version 2"

cat >"$work/frozen.yaml" <<YAML
seed: 4
world: {type: dataset, data: $work/test, model: $work/model.json}
arms:
  - {name: plan, strategy: plan}
  - {name: information_gain, strategy: information_gain}
planner: {solver: abt, episodes: 500, max_steps: 100}
YAML
"$bin" experiment --config "$work/frozen.yaml" --out "$work/frozen" >"$work/frozen.out" 2>&1 \
  || { fail "the frozen-model campaign exited $?"; cat "$work/frozen.out"; }
[ "$(($(wc -l <"$work/frozen/trials.csv") - 1))" -eq 24 ] || fail "12 sessions x 2 arms expected"

# Every trial of both arms, replayed by `run --data` with its seed: the same actions and observations.
for arm in plan information_gain; do
  solver=abt; [ "$arm" = plan ] || solver=$arm
  # (A file, not a pipe: `fail` must count in this shell.)
  awk -F, -v a="$arm" 'NR > 1 && $(NF-3) == a {print $1, $(NF-2), $(NF-1), $NF}' \
    "$work/frozen/trials.csv" >"$work/trials_$arm"
  [ -s "$work/trials_$arm" ] || fail "no $arm trials in trials.csv"
  while read -r id object session seed; do
    "$bin" run --data "$work/test" --object "$object" --session "$session" --model "$work/model.json" \
      --problem "$work/problem.yaml" --seed "$seed" --solver "$solver" --episodes 500 \
      --out "$work/run_${arm}_$id" >"$work/run.out" 2>&1 || { fail "run $arm $object exited $?"; cat "$work/run.out"; }
    ran=$(awk -F, 'NR > 1 {printf "%s:%s ", $3, $7}' "$work/run_${arm}_$id/loop_steps.csv")
    logged=$(awk -F, -v id="$id" '$1 == id {printf "%s:%s ", $3, $4}' "$work/frozen/steps.csv")
    [ -n "$ran" ] && [ "$ran" = "$logged" ] || fail "$arm $object $session: run [$ran] campaign [$logged]"
  done <"$work/trials_$arm"
done

# A model whose classes are the groups is refused by a campaign sorting objects.
"$bin" train --data "$work/train" --groups "$work/train/groups.csv" --hold-out object \
  --out "$work/groups.json" >/dev/null 2>&1 || fail "training on groups exited $?"
sed "s#model.json#groups.json#" "$work/frozen.yaml" >"$work/wrong.yaml"
"$bin" experiment --config "$work/wrong.yaml" --out "$work/wrong" >/dev/null 2>"$work/wrong.err"
[ $? -eq 2 ] || fail "a model of other classes: expected exit 2"
grep -q "groups.json: the model's classes" "$work/wrong.err" || { fail "wrong classes: unclear error"; cat "$work/wrong.err"; }

# `run --data` with a model of other classes than its problem's says so.
"$bin" run --data "$work/test" --object obj0 --session s3 --model "$work/groups.json" \
  --problem "$work/problem.yaml" --out "$work/wrong_run" >/dev/null 2>"$work/wrong_run.err"
[ $? -eq 2 ] || fail "run with a model of other classes: expected exit 2"
grep -q "the model hears \[group0" "$work/wrong_run.err" || { fail "run, wrong classes: unclear error"; cat "$work/wrong_run.err"; }

# A recordings tree with a groups file and a README beside its object folders trains.
"$bin" synth-recordings --per-pair 3 --seed 1 --objects plastic_cup,coffee_mug --actions strike \
  -o "$work/tree" >/dev/null 2>&1 || fail "synth-recordings exited $?"
printf 'object,group\nplastic_cup,plastic\ncoffee_mug,ceramic\n' >"$work/tree/groups.csv"
echo "notes" >"$work/tree/README.md"
"$bin" train --data "$work/tree" --out "$work/tree.json" >"$work/tree.out" 2>&1 \
  || { fail "train on a recordings tree with a groups file exited $?"; cat "$work/tree.out"; }

finish "one observation model CLI"
