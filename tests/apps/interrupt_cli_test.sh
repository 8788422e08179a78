#!/bin/sh
# Ctrl-C on a long command (common/stop_signal.h): the run stops after the unit in progress, keeps what it
# finished, writes its summary and exits 130. Usage: interrupt_cli_test.sh ECHOPLAN_BINARY SOURCE_DIR
. "$(dirname "$0")/cli_test_lib.sh"

# Far more trials than can finish before the signal arrives. A shell starts background jobs with SIGINT
# ignored (and echoplan keeps it so); env gives this one the default disposition, as a terminal's
# foreground job has.
env --default-signal=INT "$bin" trials --problem "$src/problems/tiger.pomdp" --solver pomcp --trials 100000 --episodes 200 --seed 1 \
  --out "$work/run" >"$work/out" 2>"$work/err" &
pid=$!
# At least one trial on disk: header plus one row.
wait_for_lines "$work/run/trials.csv" 2
kill -INT "$pid"
wait "$pid"
status=$?

[ "$status" -eq 130 ] || fail "exit status $status after SIGINT, expected 130"
grep -q '"interrupted": *true' "$work/run/summary.json" 2>/dev/null || fail "summary.json lacks \"interrupted\": true"
rows=$(($(wc -l <"$work/run/trials.csv") - 1))
[ "$rows" -ge 1 ] && [ "$rows" -lt 100000 ] || fail "trials.csv holds $rows finished trials"
grep -q "stopping after the current step" "$work/err" || fail "stderr does not say the run is stopping"

finish "interrupt CLI"
