#!/bin/sh
# Offline bounds benchmark (docs/BENCHMARKS.md, "Offline bounds"): time for `echoplan solve` to reach
# the default epsilon (median of repeated runs), and the bounds reached within fixed time limits on
# the problems that do not converge in minutes.
# Usage: bench/offline_bounds.sh BUILD_DIR [RUNS]
set -eu
build=$1
runs=${2:-5}
bin=$build/echoplan
src=$(cd "$(dirname "$0")/.." && pwd)
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT

# Median wall time (seconds, from the solver's own "seconds") of RUNS solves to the default epsilon.
median_seconds() {
  for i in $(seq "$runs"); do
    "$bin" solve --problem "$1" --json 2>/dev/null | sed 's/.*"seconds":\([0-9.e-]*\).*/\1/'
  done | sort -g | awk '{ a[NR] = $1 } END { print a[int((NR + 1) / 2)] }'
}
echo "tiger.pomdp: median seconds to epsilon 1e-4 over $runs runs: $(median_seconds "$src/problems/tiger.pomdp")"
"$bin" solve --problem "$src/problems/tiger.pomdp" --json 2>/dev/null

"$bin" make-problem --objects 16 --sensing-actions 4 --seed 1 -o "$dir/objects16.yaml" >/dev/null
"$bin" make-problem --objects 64 --sensing-actions 4 --seed 1 -o "$dir/objects64.yaml" >/dev/null
for limit in 10 60; do
  for p in "$src/problems/audio_objects.yaml" "$dir/objects16.yaml" "$dir/objects64.yaml"; do
    echo "$(basename "$p") --time-limit $limit:"
    "$bin" solve --problem "$p" --time-limit "$limit" --json 2>/dev/null
  done
done
