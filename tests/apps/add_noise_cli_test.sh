#!/bin/sh
# `echoplan add-noise` end to end (docs/noise.md): a simulated recordings tree copied with real
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

finish "add-noise"
