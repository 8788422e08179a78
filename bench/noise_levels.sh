#!/bin/sh
# Background noise (docs/BENCHMARKS.md, "Background noise"): experiments/noise.yaml with the trials'
# event-to-background ratio set to each LEVEL in turn (the same speech and room noise, the same
# seed), printing each level's paired difference and how sure each arm was at the sort against how
# often it was right. With TRAINING_SOURCES (comma-separated), the arm trained in noise learns from
# those instead (a kind of noise the trials never play).
# Usage: bench/noise_levels.sh BUILD_DIR [LEVELS] [EPISODES] [TRAINING_SOURCES]
set -eu
build=$1
levels=${2:-"12 0 -6"}
episodes=${3:-20000}
training=${4:-}
here=$(cd "$(dirname "$0")/.." && pwd)
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
for level in $levels; do
  config="$here/experiments/noise_at_$level.yaml"  # beside the original: its relative paths hold
  sed -e "s/ebr_db: \"0\"/ebr_db: \"$level\"/" -e "s/episodes: [0-9]*/episodes: $episodes/" \
    "$here/experiments/noise.yaml" >"$dir/config.yaml"
  if [ -n "$training" ]; then
    sources=$(echo "$training" | sed 's/,/, /g')
    sed -i "s|^  noise: {sources: \[.*\]}|  noise: {sources: [$sources]}|" "$dir/config.yaml"
  fi
  cp "$dir/config.yaml" "$config"
  echo "== EBR $level dB"
  "$build/echoplan" experiment --config "$config" --out "$dir/$level" 2>/dev/null |
    grep -A3 -E "minus|how sure" | grep -v -E "^--|^arm|objects|pringles|coffee"
  rm -f "$config"
done
