#!/bin/sh
# The campaign's shards as a real Slurm array job (scripts/campaign.sbatch on a one-node cluster this test
# starts itself, scripts/slurm-test-cluster.sh), merged: the same files as the unsharded run.
# Exit 77 (skipped) when Slurm is not installed. Usage: experiment_slurm_cli_test.sh ECHOPLAN_BINARY SOURCE_DIR
set -u
bin=$1
src=$2
work=$(mktemp -d)
cluster=$work/cluster
cleanup() {
  "$src/scripts/slurm-test-cluster.sh" stop "$cluster" >/dev/null 2>&1
  rm -rf "$work"
}
trap cleanup EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

start_output=$("$src/scripts/slurm-test-cluster.sh" start "$cluster" 2>"$work/start.err")
status=$?
if [ "$status" -eq 77 ]; then
  cat "$work/start.err"
  exit 77
fi
[ "$status" -eq 0 ] || { echo "FAIL: the test cluster did not start:"; cat "$work/start.err"; exit 1; }
eval "$start_output"

cat >"$work/campaign.yaml" <<YAML
seed: 8
arms:
  - {name: hand_tuned, problem: $src/problems/audio_objects.yaml}
world: {type: model, problem: $src/problems/audio_objects.yaml}
training_set: {recordings_per_pair: 1}
trials:
  - {object: pringles_can, trials: 4}
  - {object: coffee_mug_weighted, plays: coffee_mug, trials: 4}
planner: {solver: abt, episodes: 1000, max_steps: 40}
YAML

"$bin" experiment --config "$work/campaign.yaml" --out "$work/whole" >/dev/null 2>&1 || fail "unsharded run exited $?"

mkdir -p "$work/jobs/shards"
job=$(sbatch --parsable --array=1-3 --chdir="$work/jobs" --export="ALL,ECHOPLAN=$bin,CONFIG=$work/campaign.yaml" \
  "$src/scripts/campaign.sbatch" 2>"$work/sbatch.err") || { fail "sbatch failed: $(cat "$work/sbatch.err")"; exit 1; }
waited=0
while [ -n "$(squeue -h -j "$job" 2>/dev/null)" ] && [ "$waited" -lt 1200 ]; do
  sleep 0.25
  waited=$((waited + 1))
done
[ -z "$(squeue -h -j "$job" 2>/dev/null)" ] || fail "the array job did not finish in 5 minutes"
tasks=$(scontrol -o show job "$job" | grep -c "JobState=COMPLETED")
[ "$tasks" -eq 3 ] || { fail "$tasks of 3 array tasks completed"; scontrol -o show job "$job"; cat "$work"/jobs/shards/*.log; }

"$bin" merge --out "$work/merged" "$work/jobs/shards/1" "$work/jobs/shards/2" "$work/jobs/shards/3" \
  >/dev/null 2>"$work/merge.err" || { fail "merge exited $?"; cat "$work/merge.err"; }
diff -r "$work/whole" "$work/merged" >"$work/diff" 2>&1 || { fail "merged array job differs from the unsharded run"; head "$work/diff"; }

[ "$failures" -eq 0 ] && echo "all Slurm array job checks passed"
exit "$failures"
