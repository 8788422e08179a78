#!/usr/bin/env bash
# Build libFuzzer targets with clang (build-fuzz/) and run each for a bounded time, under nice -n 19.
#
#   scripts/fuzz.sh [--all | TARGET...] [--seconds N] [--no-build] [--summary FILE]
#   scripts/fuzz.sh [SECONDS] [TARGET]      the older form: one target (default audio_decode_fuzz)
#   scripts/fuzz.sh                         audio_decode_fuzz for 120 s
#
#   --all          every target in turn (the list below)
#   --seconds N    seconds per target (default 120)
#   --no-build     run what build-fuzz/ holds (another fuzz.sh is building or running in it)
#   --summary FILE where the table goes (default build-fuzz/summary.md); it is printed too
#   JOBS           (environment) parallel build jobs, default 2
#   FUZZ_BUILD_DIR (environment) the build folder, default build-fuzz (below: build-fuzz/)
#
# Targets (each reads the bytes as one kind of file or message; docs/fuzzing.md has the measured runs):
#   audio_decode_fuzz      WAV, AIFF and FLAC decoding (libsndfile) and every feature extractor
#   problem_file_fuzz      problem files: YAML and Cassandra .pomdp
#   sim_files_fuzz         the object catalogue and the simulator configuration
#   perception_model_fuzz  the observation model file (JSON)
#   policy_file_fuzz       the offline policy file (JSON alpha vectors)
#   experiment_files_fuzz  steps.csv and the campaign file
#   oppt_log_fuzz          OPPT run logs (`echoplan import oppt`)
#   feature_set_fuzz       a feature set's modality file and the groups file
#   recording_set_fuzz     a recording set's manifest.csv
#   series_file_fuzz       a sensor's series file, then every kind of series features
#   ros_audio_fuzz         ROS message bodies: Clip, Observe, FeatureRow, AudioData chunks (needs roscpp)
#   bag_messages_fuzz      the JointState, WrenchStamped and String bodies import-bag decodes (needs rosbag)
#
# Seeds: the committed corpus fuzz/corpus/<target>/ (and, for audio, the reference inputs). What a run
# adds goes to build-fuzz/corpus/<target>/, findings (crash-*, timeout-*, oom-*, leak-*) to
# build-fuzz/findings/<target>/, libFuzzer's output to build-fuzz/logs/<target>.log. Exit status: 0
# when no target found anything, 1 when one did (its findings are listed), 2 for a usage error.
set -euo pipefail

root="$(cd "$(dirname "$0")/.." && pwd)"
build="$(cd "$root" && mkdir -p "${FUZZ_BUILD_DIR:-build-fuzz}" && cd "${FUZZ_BUILD_DIR:-build-fuzz}" && pwd)"
all_targets=(audio_decode_fuzz problem_file_fuzz sim_files_fuzz perception_model_fuzz policy_file_fuzz
             experiment_files_fuzz oppt_log_fuzz feature_set_fuzz recording_set_fuzz series_file_fuzz
             ros_audio_fuzz bag_messages_fuzz)

usage() { awk 'NR > 1 && !/^#/ { exit } NR > 1 { sub(/^# ?/, ""); print }' "$0"; }
die() { echo "fuzz.sh: $1" >&2; exit 2; }

seconds=120
build_first=1
summary="$build/summary.md"
targets=()
positional=()
while [ $# -gt 0 ]; do
  case "$1" in
    -h|--help) usage; exit 0 ;;
    --all) targets=("${all_targets[@]}") ;;
    --seconds) [ $# -ge 2 ] || die "--seconds needs a number"; seconds=$2; shift ;;
    --no-build) build_first=0 ;;
    --summary) [ $# -ge 2 ] || die "--summary needs a file"; summary=$2; shift ;;
    -*) die "unknown option '$1' (see scripts/fuzz.sh --help)" ;;
    *) positional+=("$1") ;;
  esac
  shift
done
# The older form: a number first is the seconds, then at most one target.
if [ ${#positional[@]} -gt 0 ] && [[ ${positional[0]} =~ ^[0-9]+$ ]]; then
  seconds=${positional[0]}
  positional=("${positional[@]:1}")
fi
targets+=("${positional[@]}")
[ ${#targets[@]} -gt 0 ] || targets=(audio_decode_fuzz)
[[ $seconds =~ ^[0-9]+$ ]] && [ "$seconds" -gt 0 ] || die "--seconds wants a whole number > 0, got '$seconds'"
for target in "${targets[@]}"; do
  [[ " ${all_targets[*]} " == *" $target "* ]] ||
    die "unknown target '$target'; the targets: ${all_targets[*]}"
done

if [ "$build_first" = 1 ]; then
  command -v clang++ >/dev/null || die "clang++ not found (Debian package clang)"
  cmake -S "$root" -B "$build" -DECHOPLAN_BUILD_FUZZ=ON -DCMAKE_CXX_COMPILER=clang++ \
    -DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O2 -gline-tables-only -DNDEBUG" \
    -DECHOPLAN_BUILD_TESTS=OFF -DECHOPLAN_BUILD_BENCH=OFF \
    -DECHOPLAN_BUILD_PYTHON=OFF >/dev/null
  # ros_audio_fuzz exists only where roscpp was found, bag_messages_fuzz only where rosbag storage
  # was: --all goes on without them, naming one fails.
  # (The list is read whole first: grep -q closing the pipe early would fail make under pipefail.)
  known=$(cmake --build "$build" --target help)
  for optional in ros_audio_fuzz:roscpp bag_messages_fuzz:librosbag-storage-dev; do
    target=${optional%%:*}
    grep -qw "$target" <<<"$known" && continue
    [[ " ${positional[*]} " != *" $target "* ]] || die "$target needs ${optional#*:} (scripts/setup.sh deps)"
    echo "fuzz.sh: ${optional#*:} not found, so no $target" >&2
    targets=("${targets[@]/$target/}")
    read -r -a targets <<<"${targets[*]}"
  done
  cmake --build "$build" -j"${JOBS:-2}" --target "${targets[@]}"
fi

# stat NAME LOG: the value of libFuzzer's final `stat::NAME: value` line.
stat() { sed -n "s/^stat::$1: *//p" "$2" | tail -n 1; }
# status FIELD LOG: FIELD (cov, ft) of the last status line (`#N ... cov: C ft: F corp: ...`).
status() { grep -E '^#[0-9]+' "$2" | grep -o "$1: [0-9]*" | tail -n 1 | sed 's/.*: //'; }

rows=()
failed=()
for target in "${targets[@]}"; do
  binary="$build/fuzz/$target"
  [ -x "$binary" ] || die "$binary is not built (run without --no-build)"
  corpus="$build/corpus/$target"
  findings="$build/findings/$target"
  log="$build/logs/$target.log"
  mkdir -p "$corpus" "$findings" "$(dirname "$log")"
  seeds=("$root/fuzz/corpus/$target")
  [ "$target" != audio_decode_fuzz ] || seeds+=("$root/tests/data/reference/audio/inputs")
  before=$(find "$findings" -type f | wc -l)
  echo "fuzz.sh: $target for $seconds s (log: $log)"
  start=$SECONDS
  # New inputs go to the first folder, the seeds are only read. Inputs up to 4 KiB keep runs fast
  # (larger seeds are read truncated, which exercises the truncated-data path); 10 s per input or
  # 2 GiB are reported as bugs.
  status=0
  nice -n 19 "$binary" "$corpus" "${seeds[@]}" -max_total_time="$seconds" -max_len=4096 -timeout=10 \
    -rss_limit_mb=2048 -artifact_prefix="$findings/" -print_final_stats=1 >"$log" 2>&1 || status=$?
  elapsed=$((SECONDS - start))
  found=$(($(find "$findings" -type f | wc -l) - before))
  if [ "$status" -ne 0 ] || [ "$found" -gt 0 ]; then
    failed+=("$target")
    tail -n 40 "$log" >&2
  fi
  runs=$(stat number_of_executed_units "$log")
  rate=$(stat average_exec_per_sec "$log")
  seed_cov=$(grep -m 1 INITED "$log" | grep -o 'cov: [0-9]*' | sed 's/.*: //')
  rows+=("| $target | $elapsed | ${runs:-?} | ${rate:-?} | ${seed_cov:-?} | $(status cov "$log") | \
$(status ft "$log") | $(find "$corpus" -type f | wc -l) | $found |")
done

{
  echo "Fuzzing run of $(date -u '+%Y-%m-%d %H:%M UTC'), $seconds s per target, commit $(git -C "$root" rev-parse --short HEAD)"
  echo
  echo "| target | seconds | executions | exec/s | cov at start | cov (edges) | ft (features) | corpus | findings |"
  echo "| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |"
  printf '%s\n' "${rows[@]}"
} | tee "$summary"
if [ ${#failed[@]} -gt 0 ]; then
  echo "fuzz.sh: findings in ${failed[*]}: see $build/findings/ and $build/logs/" >&2
  exit 1
fi
