# Shared by the tests/apps/*_cli_test.sh scripts, which source it first: . "$(dirname "$0")/cli_test_lib.sh"
# Every script is run as <name>_cli_test.sh ECHOPLAN_BINARY SOURCE_DIR. This sets `bin` and `src` from
# those, `work` to a fresh folder removed at exit, and defines
#   fail MESSAGE   report one failed check (the script goes on, so one run lists every failure);
#   finish WHAT    print the verdict and exit with the number of failures (0: all passed);
#   expect_input_error DESCRIPTION MESSAGE ARGS...
#                  run "$bin" ARGS... and check it refuses the input as a user error: exit status 2 and
#                  MESSAGE (a grep pattern) on stderr. Its output is left in $work/out and $work/err;
#   wait_for_lines FILE LINES
#                  wait (up to 60 s) until FILE holds at least LINES lines, e.g. before interrupting a
#                  background run that has finished some work;
#   small_campaign FILE [RECORDINGS_PER_PAIR]
#                  write a small campaign on the model's own table (12 trials) to FILE, its training set
#                  RECORDINGS_PER_PAIR (1; 0: none) simulated recordings of each object and action;
#   same_files A B WHAT
#                  check every file of folder A is in B with the same bytes, and no more.
set -u
bin=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
finish() {
  [ "$failures" -eq 0 ] && echo "all $1 checks passed"
  exit "$failures"
}
expect_input_error() {
  description=$1
  message=$2
  shift 2
  "$bin" "$@" >"$work/out" 2>"$work/err"
  status=$?
  if [ "$status" -ne 2 ]; then
    fail "$description: exit status $status, expected 2"; cat "$work/err"
  elif ! grep -q -- "$message" "$work/err"; then
    fail "$description: stderr lacks '$message':"; cat "$work/err"
  fi
}
wait_for_lines() {
  waited=0
  while [ "$(cat "$1" 2>/dev/null | wc -l)" -lt "$2" ] && [ "$waited" -lt 3000 ]; do
    sleep 0.02
    waited=$((waited + 1))
  done
}
small_campaign() {
  cat >"$1" <<YAML
seed: 4
arms:
  - {name: hand_tuned, problem: $src/problems/audio_objects.yaml}
world: {type: model, problem: $src/problems/audio_objects.yaml}
training_set: {recordings_per_pair: ${2:-1}}
trials:
  - {object: pringles_can, trials: 4}
  - {object: plastic_cup, trials: 4}
  - {object: coffee_mug_weighted, plays: coffee_mug, trials: 4}
planner: {solver: abt, episodes: 1000, max_steps: 30}
YAML
}
same_files() {
  diff -r "$1" "$2" >"$work/diff" 2>&1 || { fail "$3: folders differ"; head -5 "$work/diff"; }
}
