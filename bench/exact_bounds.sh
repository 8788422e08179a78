#!/bin/sh
# Exact identification solver benchmark (docs/BENCHMARKS.md, "Exact identification solver"): the
# bounds on V*(b0) after a fixed amount of work (node expansions for the exact solver, trials for
# the point-based one, so the bounds repeat on any machine; wall time is as measured), for the report's
# problem at discount 0.99 and 0.95 and generated problems of 4, 8, 16 and 64 objects (3 sensing
# actions, 3 bins, seed 1). Each exact row is run with the frontier bounds of the default (plans +
# sawtooth + the two-state partition relaxation), with only the actions near the best case
# expanded at each belief (--expand-within 0.3), without the relaxation (the solver before it),
# with the plain bounds (commit now / one more sensing), and with HSVI-style trials; then the
# point-based solver. Prints one table row per run. PROBLEMS (environment) picks a subset, e.g.
# PROBLEMS="report099 objects8".
# Usage: bench/exact_bounds.sh BUILD_DIR [EXPANSIONS] [POINT_BASED_TRIALS]
set -eu
build=$1
expansions=${2:-200000}
trials=${3:-500}
bin=$build/echoplan
src=$(cd "$(dirname "$0")/.." && pwd)
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT

cp "$src/problems/audio_objects.yaml" "$dir/report099.yaml"
sed 's/^discount: 0.99/discount: 0.95/' "$src/problems/audio_objects.yaml" >"$dir/report095.yaml"
for n in 4 8 16 64; do
  "$bin" make-problem --objects $n --sensing-actions 3 --bins 3 --seed 1 -o "$dir/objects$n.yaml" >/dev/null
done

# The fields of one --json result: lower upper gap root_seconds work.
fields() {
  sed 's/.*"lower":\([^,]*\),"upper":\([^,]*\),"gap":\([^,]*\),.*/\1 \2 \3/' "$1" | tr '\n' ' '
  if grep -q root_seconds "$1"; then
    sed 's/.*"root_expansions":\([0-9]*\),"root_seconds":\([^,]*\),.*/\2 \1 expansions/' "$1"
  else
    sed 's/.*"trials":\([0-9]*\),"seconds":\([^,]*\),.*/\2 \1 trials/' "$1"
  fi
}

echo "| problem | method | lower | upper | gap | seconds | work |"
echo "|---|---|---|---|---|---|---|"
for p in ${PROBLEMS:-report099 report095 objects4 objects8 objects16 objects64}; do
  # frontier search pair-relaxation expand-within label
  for m in "full passes on 1 full_passes" "full passes on 0.3 full_passes,_near_the_best_case" \
    "full passes off 1 full_passes,_no_pairs" "simple passes off 1 simple_passes" \
    "full trials on 1 full_trials"; do
    set -- $m
    label=$(echo "$5" | tr _ ' ')
    "$bin" solve --problem "$dir/$p.yaml" --method exact --exact-frontier "$1" --exact-search "$2" \
      --pair-relaxation "$3" --expand-within "$4" --max-expansions "$expansions" --time-limit 600 \
      --epsilon 1e-6 --json 2>/dev/null >"$dir/out.json"
    set -- $(fields "$dir/out.json")
    printf '| %s | exact, %s | %.5f | %.5f | %.4g | %.1f | %s %s |\n' "$p" "$label" "$1" "$2" "$3" "$4" "$5" "$6"
  done
  "$bin" solve --problem "$dir/$p.yaml" --method point-based --max-trials "$trials" \
    --time-limit 600 --epsilon 1e-6 --json 2>/dev/null >"$dir/out.json"
  set -- $(fields "$dir/out.json")
  printf '| %s | point-based | %.5f | %.5f | %.4g | %.1f | %s %s |\n' "$p" "$1" "$2" "$3" "$4" "$5" "$6"
done
