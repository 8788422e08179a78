#!/bin/sh
# `echoplan train`, `classify` and `evaluate` end to end on a small simulated dataset: the outputs a user
# relies on, the problem file the planner reads back, and exit status 2 with a message for bad input.
# Usage: perception_cli_test.sh ECHOPLAN_BINARY SOURCE_DIR
. "$(dirname "$0")/cli_test_lib.sh"

# Three recordings per (object, action) of the report's problem's four objects; a second seed is held out.
objects=pringles_can,coffee_mug,plastic_cup,paper_base
"$bin" synth-recordings --per-pair 3 --seed 1 --objects $objects -o "$work/data" >/dev/null 2>&1 || fail "dataset 1"
"$bin" synth-recordings --per-pair 2 --seed 2 --objects $objects -o "$work/held" >/dev/null 2>&1 || fail "dataset 2"

"$bin" train --data "$work/data" --out "$work/model.json" --problem-out "$work/problem.yaml" \
  --problem-base "$src/problems/audio_objects.yaml" >"$work/train.out" 2>"$work/train.err" || { fail "train exited $?"; cat "$work/train.err"; }
grep -q "strike (cross-validated, leave-one-out): accuracy" "$work/train.out" || fail "train prints the strike accuracy"
grep -q "slide (cross-validated, leave-one-out): accuracy" "$work/train.out" || fail "train prints the slide accuracy"
# The problem file loads and plans with the calibrated symbols, `unknown` included.
"$bin" check --problem "$work/problem.yaml" >"$work/check.out" 2>&1 || { fail "check of the written problem exited $?"; cat "$work/check.out"; }
grep -q "symbols: \[pringles_can, coffee_mug, plastic_cup, paper_base, unknown\]" "$work/problem.yaml" \
  || fail "problem symbols: $(grep symbols "$work/problem.yaml")"

# --table soft: the model file records it, and the problem file's header says which table it holds.
"$bin" train --data "$work/data" --out "$work/soft.json" --table soft --problem-out "$work/soft.yaml" \
  --problem-base "$src/problems/audio_objects.yaml" >/dev/null 2>"$work/soft.err" || { fail "train --table soft exited $?"; cat "$work/soft.err"; }
grep -q '"table_estimate":"soft"' "$work/soft.json" || fail "the model file records table_estimate soft"
grep -q '"table_estimate":"counts"' "$work/model.json" || fail "the default model file records its table estimate"
grep -q "soft table" "$work/soft.yaml" || fail "the problem header names the soft table"

# classify --json: one object per file with the documented fields; probabilities sum to 1.
"$bin" classify --model "$work/model.json" --action strike --json "$work/held/coffee_mug/strike/000.wav" \
  "$work/held/paper_base/strike/001.wav" >"$work/classify.out" 2>"$work/classify.err" || fail "classify exited $?"
[ "$(wc -l <"$work/classify.out")" -eq 2 ] || fail "classify --json printed $(wc -l <"$work/classify.out") lines for 2 files"
/usr/bin/python3 - "$work/classify.out" <<'PY' || fail "classify --json lines"
import json, sys
lines = [json.loads(l) for l in open(sys.argv[1])]
for l in lines:
    assert set(l) == {"file", "action", "class", "probabilities", "distance"}, l
    assert l["action"] == "strike"
    assert abs(sum(l["probabilities"].values()) - 1) < 1e-9, l
    assert set(l["probabilities"]) == {"pringles_can", "coffee_mug", "plastic_cup", "paper_base"}
assert lines[0]["file"].endswith("coffee_mug/strike/000.wav")
PY
"$bin" classify --model "$work/model.json" --action slide "$work/held/plastic_cup/slide/000.wav" >"$work/c.out" 2>&1 \
  || fail "classify (text) exited $?"
grep -q "plastic_cup/slide/000.wav: " "$work/c.out" || fail "classify text output: $(cat "$work/c.out")"

# evaluate --json on the held-out seed.
"$bin" evaluate --model "$work/model.json" --data "$work/held" --json >"$work/eval.out" 2>/dev/null || fail "evaluate exited $?"
/usr/bin/python3 - "$work/eval.out" <<'PY' || fail "evaluate --json document"
import json, sys
d = json.load(open(sys.argv[1]))
assert set(d["actions"]) == {"slide", "strike"}, d
for m in d["actions"].values():
    assert sum(map(sum, m["confusion"])) == 8 and m["symbols"][-1] == "unknown" and 0 <= m["accuracy"] <= 1
PY

# Bad input: exit 2 with a message naming the problem.
expect_input_error "missing data" "does not exist" train --data "$work/nope" --out "$work/m.json"
expect_input_error "unknown classifier" "classifier" train --data "$work/data" --out "$work/m.json" --classifier magic
expect_input_error "unknown table estimate" "--table: hard not in {counts,soft,shrunk}" train --data "$work/data" --out "$work/m.json" --table hard
expect_input_error "problem base of another kind" "not an object-identification problem" train --data "$work/held" \
  --out "$work/m.json" --problem-out "$work/p.yaml" --problem-base "$src/problems/tiger.pomdp"
mkdir -p "$work/two" && cp -r "$work/held/coffee_mug" "$work/held/plastic_cup" "$work/two/"
expect_input_error "problem object without recordings" "object 'pringles_can' of the problem has no recordings" train \
  --data "$work/two" --out "$work/m.json" --problem-out "$work/p.yaml" --problem-base "$src/problems/audio_objects.yaml"
mkdir -p "$work/odd/mug/strike"
expect_input_error "empty class folder" "no recordings in this" train --data "$work/odd" --out "$work/m.json"
expect_input_error "missing model" "cannot open the model file" classify --model "$work/none.json" --action strike "$work/held/coffee_mug/strike/000.wav"
head -c 300 "$work/model.json" >"$work/truncated.json"
expect_input_error "truncated model" "not a valid JSON model file" classify --model "$work/truncated.json" --action strike x.wav
expect_input_error "unknown action" "action 'shake' is not in the model" classify --model "$work/model.json" --action shake "$work/held/coffee_mug/strike/000.wav"
echo "not audio" >"$work/bad.wav"
expect_input_error "corrupt recording" "bad.wav" classify --model "$work/model.json" --action strike "$work/bad.wav"
expect_input_error "evaluate on missing folder" "does not exist" evaluate --model "$work/model.json" --data "$work/nope"

# Each table held out in turn: a set recorded on two tables (recording i of each pair on table i mod 2)
# is cross-validated table by table; one recorded on the lab's table alone names no table.
"$bin" synth-recordings --per-pair 4 --seed 3 --objects plastic_cup,paper_base --surface lab_laminate,rubber_mat \
  -o "$work/tables" >/dev/null 2>&1 || fail "dataset on two tables"
"$bin" train --data "$work/tables" --cross-validation surface --out "$work/tables.json" >"$work/tables.out" 2>"$work/tables.err" \
  || { fail "train by surface exited $?"; cat "$work/tables.err"; }
grep -q "strike (cross-validated, each table held out): accuracy [0-9.]* (\([0-9]*\) of 8)" "$work/tables.out" \
  || { fail "train by surface does not print the accuracy of 8 held-out strikes"; cat "$work/tables.out"; }
"$bin" evaluate --model "$work/model.json" --data "$work/tables" >"$work/eval_tables.out" 2>/dev/null \
  || fail "evaluate on two tables exited $?"
grep -q "^  per table: lab_laminate [0-9.]* ([0-9]* of 4), rubber_mat [0-9.]* ([0-9]* of 4)$" "$work/eval_tables.out" \
  || { fail "evaluate does not count each table's 4 recordings of an action"; cat "$work/eval_tables.out"; }
"$bin" evaluate --model "$work/model.json" --data "$work/tables" --json 2>/dev/null \
  | /usr/bin/python3 -c "import json,sys; d=json.load(sys.stdin); assert sorted(d['surfaces']) == ['lab_laminate', 'rubber_mat']" \
  || fail "evaluate --json has no surfaces"
"$bin" evaluate --model "$work/model.json" --data "$work/held" 2>/dev/null | grep -q "per table" \
  && fail "evaluate on a set without tables prints tables"
grep -q '"surfaces"' "$work/eval.out" && fail "evaluate --json on a set without tables has surfaces"
expect_input_error "cross-validation by surface on one table" "names no table" \
  train --data "$work/data" --cross-validation surface --out "$work/x.json"
expect_input_error "cross-validation by surface with a hold-out" "make folds of objects" \
  train --data "$work/tables" --cross-validation surface --hold-out object --out "$work/x.json"

finish "perception CLI"
