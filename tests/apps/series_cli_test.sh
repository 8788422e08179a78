#!/bin/sh
# A robot that feels instead of hearing: a recordings tree of joint-effort series alone
# (<name>.effort.csv, no audio) trains with `train --series effort=cy101-haptic`, the model file says
# how its rows were computed, `run --data` replays a session with those features, and bad --series
# values are refused as user errors.
# Usage: series_cli_test.sh ECHOPLAN_BINARY SOURCE_DIR
. "$(dirname "$0")/cli_test_lib.sh"

# Three objects of efforts 1, 2 and 4 N m (with per-sample wobble), lifted and pressed in four
# sessions; 20 samples at 100 Hz each.
python3 - "$work/tree" <<'PY' || fail "writing the tree"
import math, os, sys
root = sys.argv[1]
rows = ["file,object,action,session"]
for o, (name, weight) in enumerate((("light", 1.0), ("middle", 2.0), ("heavy", 4.0))):
    for action in ("lift", "press"):
        folder = os.path.join(root, name, action)
        os.makedirs(folder, exist_ok=True)
        for s in range(4):
            path = os.path.join(folder, f"s{s}.effort.csv")
            with open(path, "w") as f:
                f.write("t,j1,j2\n")
                for i in range(20):
                    wobble = 0.1 * math.sin(1.7 * i + 3.1 * s + o)
                    f.write(f"{i / 100},{weight * (1 + i / 20) + wobble},{0.5 * weight + wobble}\n")
            rows.append(f"{name}/{action}/s{s}.effort.csv,{name},{action},s{s}")
open(os.path.join(root, "manifest.csv"), "w").write("\n".join(rows) + "\n")
PY

"$bin" train --data "$work/tree" --series "effort=cy101-haptic" --hold-out session \
  --out "$work/model.json" --problem-out "$work/problem.yaml" >"$work/train.out" 2>&1 \
  || { fail "train exited $?"; cat "$work/train.out"; }
grep -q '"series":"bins(10,sum,time-major)"' "$work/model.json" || fail "the model does not keep its series features"
grep -q 'effort' "$work/train.out" || fail "train does not report the effort modality"

"$bin" run --data "$work/tree" --object heavy --session s2 --model "$work/model.json" \
  --problem "$work/problem.yaml" --seed 1 --episodes 300 --out "$work/run" >"$work/run.out" 2>&1 \
  || { fail "run exited $?"; cat "$work/run.out"; }
[ -s "$work/run/loop_steps.csv" ] || fail "run wrote no steps"
grep -q 'heavy' "$work/run/loop_steps.csv" || fail "the replayed heavy session was never heard as heavy"

expect_input_error "a --series without features" "expected MODALITY=FEATURES" \
  train --data "$work/tree" --series effort --out "$work/x.json"
expect_input_error "a bad series spec" "whole number from 1" \
  train --data "$work/tree" --series "effort=bins(0,sum)" --out "$work/x.json"
expect_input_error "a series the tree does not have" "no performance has a 'vision' series" \
  train --data "$work/tree" --series "vision=stats" --out "$work/x.json"
expect_input_error "too few samples for the bins" "fewer than the 40 bins" \
  train --data "$work/tree" --series "effort=bins(40,mean)" --out "$work/x.json"
finish "series"
