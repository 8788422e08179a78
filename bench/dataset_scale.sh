#!/bin/sh
# Planning on recorded data at scale (docs/BENCHMARKS.md, "Planning on recorded data at scale").
# Makes synthetic feature sets of 20 objects (sorted by object) and 100 objects (20 categories of 5,
# sorted by category), 9 behaviours whose informativeness differs, 5 sessions per object; trains
# each into a problem (`echoplan train --problem-out`, uses: 1 per behaviour) and an unlimited copy;
# then, per problem: ABT's CPU seconds per decision (the start-up of a run, one trial at one
# episode, taken off) and peak memory at the problem's default budget, 2000 and 20000 episodes
# (`echoplan trials`, TRIALS trials), the exact solver's bounds after SOLVE_SECONDS
# (`echoplan solve --method exact`), and `echoplan certify` on the 2000-episode run's steps.
# Usage: bench/dataset_scale.sh BUILD_DIR [TRIALS] [SOLVE_SECONDS] [CERTIFY_ROOT_EXPANSIONS]
set -eu
build=$1
trials=${2:-10}
solve_seconds=${3:-60}
certify_root=${4:-100000}
bin=$build/echoplan
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
actions=press,grasp,lift,drop,poke,push,shake,tap,squeeze
scales=0.3,0.4,0.5,0.6,0.7,0.8,0.9,1.0,1.2

"$build/bench/make_feature_set" -o "$dir/fs20" --objects 20 --sessions 5 --actions $actions \
  --action-scales $scales --modality audio:8:1.5 --modality haptic:4:1.0 --session-sd 0.3 --seed 1
"$build/bench/make_feature_set" -o "$dir/fs100" --objects 100 --group-size 5 --sessions 5 \
  --actions $actions --action-scales $scales --modality audio:8:1.5 --modality haptic:4:1.0 \
  --group-separation 1.0 --session-sd 0.3 --seed 1
"$bin" train --data "$dir/fs20" --problem-out "$dir/c20_uses1.yaml" >/dev/null 2>&1
"$bin" train --data "$dir/fs100" --groups "$dir/fs100/groups.csv" \
  --problem-out "$dir/c100_uses1.yaml" >/dev/null 2>&1
# The unlimited copies: the uses block removed.
for n in 20 100; do
  awk '/^  uses:/ {skip = 1; next} skip && /^    / {next} {skip = 0; print}' \
    "$dir/c${n}_uses1.yaml" >"$dir/c${n}_unlimited.yaml"
done

# "seconds max_kb" of a command, from /usr/bin/time (user + system CPU, peak resident memory);
# its standard output goes to $dir/out.
measure() {
  /usr/bin/time -f "%U %S %M" -o "$dir/time" "$@" >"$dir/out" 2>/dev/null
  awk '{printf "%.2f %d", $1 + $2, $3}' "$dir/time"
}
# Mean steps per trial of a trials.csv (the decisions a trial made).
decisions() { awk -F, 'NR > 1 {s += $4; n++} END {printf "%d", s}' "$1/trials.csv"; }

# A decision's CPU excludes what every run pays once (reading a 2 MB problem, building the model):
# the CPU of one trial at one episode per step, subtracted before dividing by the decisions.
echo "| problem | ABT episodes | trials | decisions | CPU s per decision | start-up CPU s | peak MB |"
echo "|---|---|---|---|---|---|---|"
for p in c20_uses1 c20_unlimited c100_uses1 c100_unlimited; do
  set -- $(measure "$bin" trials --problem "$dir/$p.yaml" --trials 1 --solver abt --episodes 1 \
    --seed 1 --out "$dir/start_$p")
  start=$1
  for e in default 2000 20000; do
    budget="--episodes $e"
    [ "$e" = default ] && budget=""  # the problem file's own (train writes 1000)
    set -- $(measure "$bin" trials --problem "$dir/$p.yaml" --trials "$trials" --solver abt \
      $budget --seed 1 --out "$dir/run_${p}_$e")
    d=$(decisions "$dir/run_${p}_$e")
    printf '| %s | %s | %d | %d | %.3f | %.2f | %.0f |\n' "$p" $e "$trials" "$d" \
      "$(echo "($1 - $start) / $d" | bc -l)" "$start" "$(echo "$2 / 1024" | bc -l)"
  done
done

echo
echo "| problem | exact solver, $solve_seconds s: lower | upper | gap | CPU s | peak MB |"
echo "|---|---|---|---|---|---|"
for p in c20_uses1 c20_unlimited c100_uses1 c100_unlimited; do
  set -- $(measure "$bin" solve --problem "$dir/$p.yaml" --method exact \
    --time-limit "$solve_seconds" --json)
  b=$(sed 's/.*"lower":\([^,]*\),"upper":\([^,]*\),"gap":\([^,]*\),.*/\1 \2 \3/' "$dir/out")
  set -- $b $1 $2
  printf '| %s | %.4f | %.4f | %.4g | %.1f | %.0f |\n' "$p" "$1" "$2" "$3" "$4" \
    "$(echo "$5 / 1024" | bc -l)"
done

echo
echo "certify on each 2000-episode run's steps (--root-expansions $certify_root, --expansions 2000):"
for p in c20_uses1 c20_unlimited c100_uses1 c100_unlimited; do
  set -- $(measure "$bin" certify --problem "$dir/$p.yaml" --steps "$dir/run_${p}_2000/steps.csv" \
    --root-expansions "$certify_root" --expansions 2000)
  echo "## $p: $1 CPU s, $(echo "$2 / 1024" | bc -l | cut -d. -f1) MB"
  head -12 "$dir/out"
done
