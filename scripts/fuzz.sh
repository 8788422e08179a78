#!/usr/bin/env bash
# Build a libFuzzer target with clang and run it for a bounded time, seeded with the shipped inputs:
#   audio_decode_fuzz   audio decoding + feature extraction (seeds: the reference audio inputs)
#   problem_file_fuzz   problem files, YAML and Cassandra .pomdp (seeds: problems/)
#   sim_files_fuzz      the object catalogue and simulator configuration (seeds: objects/)
#   perception_model_fuzz  the observation model file reader (seeds: tests/data/perception/*.json)
#   policy_file_fuzz    the offline policy file reader (seeds: tests/data/policy/*.json)
#   experiment_files_fuzz  steps.csv and campaign files (seeds: tests/data/experiment/, experiments/)
#   oppt_log_fuzz       OPPT run logs for `echoplan import oppt` (seeds: tests/data/oppt/)
#   feature_set_fuzz    feature-set modality and groups files (seeds: tests/data/feature_set/)
# Usage: scripts/fuzz.sh [seconds=120] [target=audio_decode_fuzz]
# Findings (crash-*, timeout-*, oom-* files) land in build-fuzz/findings/<target>/; the growing corpus in
# build-fuzz/corpus/<target>/.
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
findings="$build/findings/$target"
mkdir -p "$corpus" "$findings"
case "$target" in
  audio_decode_fuzz) seeds=("$root"/tests/data/reference/audio/inputs/*) ;;
  problem_file_fuzz) seeds=("$root"/problems/*) ;;
  sim_files_fuzz) seeds=("$root"/objects/*) ;;
  perception_model_fuzz) seeds=("$root"/tests/data/perception/*.json) ;;
  policy_file_fuzz) seeds=("$root"/tests/data/policy/*.json) ;;
  experiment_files_fuzz) seeds=("$root"/tests/data/experiment/* "$root"/experiments/*.yaml) ;;
  oppt_log_fuzz) seeds=("$root"/tests/data/oppt/*.log) ;;
  feature_set_fuzz) seeds=("$root"/tests/data/feature_set/*) ;;
  *) echo "fuzz.sh: unknown target '$target' (audio_decode_fuzz, problem_file_fuzz, sim_files_fuzz, perception_model_fuzz, policy_file_fuzz, experiment_files_fuzz, oppt_log_fuzz or feature_set_fuzz)" >&2; exit 2 ;;
esac
cp -n "${seeds[@]}" "$corpus/" 2>/dev/null || true
# One worker; inputs up to 4 KiB keep runs fast (~150/s; larger seeds are read truncated, which exercises the
# truncated-data path); 10 s per input or 2 GiB are reported as bugs.
"$build/fuzz/$target" "$corpus" -max_total_time="$seconds" -max_len=4096 -timeout=10 \
  -rss_limit_mb=2048 -artifact_prefix="$findings/" -print_final_stats=1
