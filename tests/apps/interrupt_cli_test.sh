#!/bin/sh
# Ctrl-C on a long command (common/stop_signal.h): the run stops after the unit in progress, keeps what it
# finished, writes its summary and exits 130. Usage: interrupt_cli_test.sh ECHOPLAN_BINARY SOURCE_DIR
set -u
bin=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

# Far more trials than can finish before the signal arrives.
"$bin" trials --problem "$src/problems/tiger.pomdp" --solver pomcp --trials 100000 --episodes 200 --seed 1 \
  --out "$work/run" >"$work/out" 2>"$work/err" &
pid=$!
# Wait (up to 60 s) until at least one trial is on disk: header plus one row.
waited=0
while [ "$(cat "$work/run/trials.csv" 2>/dev/null | wc -l)" -lt 2 ] && [ "$waited" -lt 600 ]; do
  sleep 0.1
  waited=$((waited + 1))
done
kill -INT "$pid"
wait "$pid"
status=$?

[ "$status" -eq 130 ] || fail "exit status $status after SIGINT, expected 130"
grep -q '"interrupted": *true' "$work/run/summary.json" 2>/dev/null || fail "summary.json lacks \"interrupted\": true"
rows=$(($(wc -l <"$work/run/trials.csv") - 1))
[ "$rows" -ge 1 ] && [ "$rows" -lt 100000 ] || fail "trials.csv holds $rows finished trials"
grep -q "stopping after the current step" "$work/err" || fail "stderr does not say the run is stopping"

[ "$failures" -eq 0 ] && echo "all interrupt CLI checks passed"
exit "$failures"
