#!/usr/bin/env bash
# Build a libFuzzer target with clang and run it for a bounded time, seeded with the repository's inputs.
# Usage: scripts/fuzz.sh [seconds=120] [target=audio_decode_fuzz]
#   audio_decode_fuzz      audio decoding + feature extraction (seeds: reference audio inputs)
#   perception_model_fuzz  the observation model file reader (seeds: tests/data/perception/*.json)
# Findings (crash-*, timeout-*, oom-* files) land in build-fuzz/findings/; the growing corpus in
# build-fuzz/corpus/.
set -euo pipefail
seconds="${1:-120}"
target="${2:-audio_decode_fuzz}"
root="$(cd "$(dirname "$0")/.." && pwd)"
build="$root/build-fuzz"
command -v clang++ >/dev/null || { echo "fuzz.sh: clang++ not found (Debian package clang)" >&2; exit 2; }
cmake -S "$root" -B "$build" -DECHOPLAN_BUILD_FUZZ=ON -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DECHOPLAN_BUILD_TESTS=OFF -DECHOPLAN_BUILD_BENCH=OFF >/dev/null
cmake --build "$build" -j2 --target "$target"
corpus="$build/corpus/$target"
mkdir -p "$corpus" "$build/findings"
case "$target" in
  audio_decode_fuzz) cp -n "$root"/tests/data/reference/audio/inputs/* "$corpus/" 2>/dev/null || true ;;
  perception_model_fuzz) cp -n "$root"/tests/data/perception/*.json "$corpus/" 2>/dev/null || true ;;
  *) echo "fuzz.sh: unknown target '$target' (audio_decode_fuzz or perception_model_fuzz)" >&2; exit 2 ;;
esac
# One worker; inputs up to 4 KiB keep runs fast (~150/s; larger seeds are read truncated, which exercises the
# truncated-data path); 10 s per input or 2 GiB are reported as bugs.
"$build/fuzz/$target" "$corpus" -max_total_time="$seconds" -max_len=4096 -timeout=10 \
  -rss_limit_mb=2048 -artifact_prefix="$build/findings/" -print_final_stats=1
