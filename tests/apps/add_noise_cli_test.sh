#!/bin/sh
# `echoplan add-noise` and `run --noise` end to end (docs/noise.md): a simulated recordings tree copied with real
# speech (the Debian package scripts/setup.sh installs) and built-in noise; the copy is a
# recordings tree the other commands read, its manifest says each recording's ratio and source,
# the same seed writes the same bytes, and bad input is refused naming it.
# Usage: add_noise_cli_test.sh ECHOPLAN_BINARY SOURCE_DIR
. "$(dirname "$0")/cli_test_lib.sh"
speech=/usr/share/asterisk/sounds/en_US_f_Allison
"$bin" synth-recordings --per-pair 2 --seed 1 --objects plastic_cup,coffee_mug --actions strike \
  -o "$work/clean" >/dev/null 2>&1 || fail "synth-recordings exited $?"

"$bin" add-noise --data "$work/clean" --noise "$speech" room --ebr -6:12 --seed 4 -o "$work/noisy" \
  >"$work/noisy.out" 2>&1 || { fail "add-noise exited $?"; cat "$work/noisy.out"; }
python3 - "$work/noisy/manifest.csv" "$speech" <<'PY' || fail "the noisy manifest: see above"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
bad = 0
if len(rows) != 4 or list(rows[0]) != ["file", "object", "action", "session", "ebr_db", "noise"]:
    print("rows", len(rows), list(rows[0]) if rows else None); bad += 1
for r in rows:
    if not -6 <= float(r["ebr_db"]) <= 12:
        print("ratio", r); bad += 1
    if r["noise"] != "room" and not r["noise"].startswith(sys.argv[2] + "/"):
        print("source", r); bad += 1
sys.exit(bad)
PY
"$bin" train --data "$work/noisy" --out "$work/noisy.json" >/dev/null 2>&1 || fail "train on the noisy copy exited $?"

"$bin" add-noise --data "$work/clean" --noise "$speech" room --ebr -6:12 --seed 4 -o "$work/again" \
  >/dev/null 2>&1 || fail "add-noise (again) exited $?"
same_files "$work/noisy" "$work/again" "the same seed's copy"

expect_input_error "a missing source" "$work/nope.wav" \
  add-noise --data "$work/clean" --noise "$work/nope.wav" --ebr 0 -o "$work/x"
expect_input_error "a bad ratio" "EBR '12:-6'" \
  add-noise --data "$work/clean" --noise white --ebr 12:-6 -o "$work/x"
expect_input_error "the copy over its source" "another folder than the data" \
  add-noise --data "$work/clean" --noise white --ebr 0 -o "$work/clean"

# A multi-condition copy: each quiet recording beside its noisy twin, both in one session.
"$bin" add-noise --data "$work/clean" --noise white --ebr 0 --keep-quiet -o "$work/both" \
  >/dev/null 2>&1 || fail "add-noise --keep-quiet exited $?"
python3 - "$work/both/manifest.csv" "$work/clean" "$work/both" <<'PY' || fail "the --keep-quiet copy: see above"
import csv, filecmp, os, sys
rows = list(csv.DictReader(open(sys.argv[1])))
bad = 0
quiet = [r for r in rows if r["noise"] == "none"]
noisy = [r for r in rows if r["noise"] == "white"]
if len(quiet) != 4 or len(noisy) != 4:
    print("rows", rows); bad += 1
for q in quiet:
    twin = [n for n in noisy if n["file"] == q["file"].replace(".wav", ".noisy.wav")]
    if len(twin) != 1 or twin[0]["session"] != q["session"] or q["ebr_db"] != "":
        print("twin of", q, twin); bad += 1
    if not filecmp.cmp(os.path.join(sys.argv[2], q["file"]), os.path.join(sys.argv[3], q["file"]), shallow=False):
        print("the quiet copy differs:", q["file"]); bad += 1
sys.exit(bad)
PY

# `run` through noise: every heard clip's measured ratio follows the room noise at +6 dB (about
# 6 to 9 dB: the loudest window holds event and noise), the quiet run's is the lab's (above 40 dB),
# and trial.json says what the trial heard.
"$bin" synth-recordings --per-pair 3 --seed 2 -o "$work/train" >/dev/null 2>&1 || fail "synth-recordings (train) exited $?"
"$bin" train --data "$work/train" --out "$work/model.json" >/dev/null 2>&1 || fail "train exited $?"
for run in quiet noisy; do
  extra=""; [ $run = noisy ] && extra="--noise room --ebr 6"
  # shellcheck disable=SC2086
  "$bin" run --object coffee_mug --model "$work/model.json" --episodes 300 --max-steps 4 $extra \
    --out "$work/$run" >"$work/$run.out" 2>&1 || { fail "run ($run) exited $?"; cat "$work/$run.out"; }
done
python3 - "$work/quiet" "$work/noisy" <<'PY' || fail "run --noise: see above"
import csv, json, sys
bad = 0
for folder, low, high in ((sys.argv[1], 40, 120), (sys.argv[2], 5, 10)):
    heard = [r for r in csv.DictReader(open(folder + "/loop_steps.csv")) if r["clip"]]
    if not heard:
        print(folder, "heard nothing"); bad += 1
    for r in heard:
        if not low <= float(r["heard_ebr_db"]) <= high:
            print(folder, "measured", r["heard_ebr_db"], "outside", low, high); bad += 1
noise = json.load(open(sys.argv[2] + "/trial.json")).get("noise")
if noise != {"sources": ["room"], "ebr_db": "6"}:
    print("trial.json noise:", noise); bad += 1
sys.exit(bad)
PY
grep -q "through room at 6 dB EBR" "$work/noisy.out" || fail "run does not say it hears noise"
expect_input_error "--ebr without --noise" "--ebr needs --noise" \
  run --object coffee_mug --model "$work/model.json" --ebr 0 --out "$work/x"
expect_input_error "--noise with recorded data" "--noise is heard by the simulator" \
  run --data "$work/train" --object coffee_mug --session s --model "$work/model.json" --noise room --ebr 0 --out "$work/x"

finish "add-noise"
