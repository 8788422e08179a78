#!/usr/bin/env bash
# echoplan setup: installs every dependency from Debian 12 packages, builds, and optionally runs.
#
#   scripts/setup.sh          install dependencies, build (build/) and install the Python module
#                             `echoplan` where Debian's python3 finds it (docs/python.md)
#   scripts/setup.sh run      install dependencies, build the `echoplan` command only, run the
#                             main job with its default configuration, then build and install the
#                             Python module (after the job, so the job starts as soon as it can)
#   scripts/setup.sh test     install dependencies, build, and run all tests: the normal build (with
#                             the Python module's), an install into a temporary prefix with a project
#                             built on it (scripts/check-install.sh), an ASan+UBSan build, a
#                             ThreadSanitizer build of the tests that start threads, and every
#                             libFuzzer target built with clang and run briefly (scripts/fuzz.sh)
#   scripts/setup.sh deps     only install dependencies
#
# Compiles go through Debian's ccache when it is installed (setup installs it): its cache (by
# default ~/.cache/ccache, ECHOPLAN_CCACHE=0 turns it off) outlives the build folders, and paths are
# taken relative to the checkout, so a fresh clone in another folder compiles from the cache what an
# earlier run on this machine compiled. A first run on a bare machine fills it (docs/BENCHMARKS.md,
# "Building and testing" has both times).
#
# Environment: JOBS (parallel build jobs, default: number of cores), BUILD_DIR (default: build),
# SAN_BUILD_DIR (default: build-san), TSAN_BUILD_DIR (default: build-tsan), ECHOPLAN_CHECK_FORMAT (1: `test` first checks the layout of every
# C++ file with scripts/check-format.sh; default 1; 0 skips it), ECHOPLAN_INSTALL_PYTHON (1: after
# building, `cmake --install BUILD_DIR --component python` puts the module under PYTHON_PREFIX,
# default /usr/local, on Debian python3's path; default 1; 0 skips it), FUZZ_SECONDS (how long `test`
# runs each fuzz target; default 5).
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$here"
mode=${1:-build}
jobs=${JOBS:-$(nproc)}
build_dir=${BUILD_DIR:-build}
san_build_dir=${SAN_BUILD_DIR:-build-san}
tsan_build_dir=${TSAN_BUILD_DIR:-build-tsan}
# The tests that start threads (the shared job pool, the campaign's parallel workers, parallel synthesis, the capture
# callback of live recording), their binaries and a ctest pattern for them: the ThreadSanitizer build
# runs these only (the rest of the suite is single-threaded, and the ASan build runs all of it).
tsan_targets=(common_tests campaign_tests sim_tests portaudio_recorder_tests)
tsan_tests='^common_tests\.ParallelJobs\.|^campaign_tests\.Campaign\.|^sim_tests\.Dataset\.|^portaudio_recorder_tests\.'

# Keep this list in one place: docs/getting-started.md points here.
packages=(
  build-essential cmake pkg-config git
  ccache                     # the compiler cache above
  lld                        # LLVM's linker: links the test binaries about 4x faster than ld.bfd
  libgtest-dev libgmock-dev libbenchmark-dev
  libyaml-cpp-dev nlohmann-json3-dev libcli11-dev libspdlog-dev libfmt-dev
  libsndfile1-dev libsamplerate0-dev libkissfft-dev
  libmujoco-dev libqhull-dev libeigen3-dev
  gnuplot-nox
  slurmctld slurmd slurm-client   # tests/apps/experiment_slurm_cli_test.sh: a one-node cluster runs an array job
  chromium                        # tests/apps/experiment_html_cli_test.sh: the campaign page rendered headless
  clang libclang-rt-14-dev   # scripts/fuzz.sh (libFuzzer)
  clang-format-14            # scripts/check-format.sh
  python3-numpy python3-scipy python3-soundfile python3-yaml  # bench/*.py (with /usr/bin/python3)
  pybind11-dev python3-dev python3-pytest  # the Python module (python/) and its tests
  portaudio19-dev            # live capture: echoplan devices/record, the ROS listener
  asterisk-core-sounds-en-wav  # real speech (CC-BY-SA-3.0) for background noise: docs/noise.md
  # ROS 1 from Debian (docs/real-robot.md): nodes, their services, a master and roslaunch for the ros_* tests
  libroscpp-dev catkin ros-message-generation libstd-msgs-dev
  python3-roslaunch python3-rosparam python3-rosservice python3-rostest librostest-dev
  python3-rospy              # tests/robot/ros/audio_capture_stand_in.py: a stand-in audio_capture node
  librosbag-storage-dev      # echoplan import-bag (robot/ros/bag_import.h)
  python3-rosbag python3-sensor-msgs python3-geometry-msgs   # its tests write bags with rosbag
)

# Every compile through ccache (CMake reads these when a build folder is configured the first
# time; scripts/fuzz.sh and scripts/check-install.sh inherit them). BASEDIR and NOHASHDIR make a
# compile independent of where the checkout is: the debug line tables then name the first clone's
# folder, which is all a sanitizer report needs.
use_compiler_cache() {
  [ "${ECHOPLAN_CCACHE:-1}" = 1 ] && command -v ccache >/dev/null || return 0
  export CMAKE_CXX_COMPILER_LAUNCHER=ccache CMAKE_C_COMPILER_LAUNCHER=ccache
  export CCACHE_BASEDIR=$here CCACHE_NOHASHDIR=1 CCACHE_MAXSIZE=${CCACHE_MAXSIZE:-20G}
}

# Links with lld when it is installed (CMake takes LDFLAGS when a build folder is configured the
# first time): a campaign test binary links in 0.15 s instead of ld.bfd's 0.72, and every build
# of `test` links some fifty.
use_fast_linker() {
  command -v ld.lld >/dev/null || return 0
  export LDFLAGS="${LDFLAGS:+$LDFLAGS }-fuse-ld=lld"
}

# stage NAME: prints how long the previous stage of `test` took and starts timing NAME.
stage_name=""
stage_start=$SECONDS
stage() {
  [ -z "$stage_name" ] || echo "setup: $stage_name took $((SECONDS - stage_start)) s"
  stage_name=$1
  stage_start=$SECONDS
}

install_deps() {
  local missing=()
  for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  if [ ${#missing[@]} -eq 0 ]; then
    echo "setup: all ${#packages[@]} Debian packages already installed"
    return
  fi
  echo "setup: installing ${missing[*]}"
  local sudo=()
  [ "$(id -u)" -eq 0 ] || sudo=(sudo)
  "${sudo[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
}

# Optimized with line tables (-g1): backtraces and sanitizer reports name file and line, and the
# build takes a quarter less time than with full debug info (-g). For a debugger, configure a
# build folder of your own with -DCMAKE_BUILD_TYPE=Debug.
release=(-DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O2 -g1 -DNDEBUG")

build() {  # build DIR [extra cmake args...]: every target (tests, benchmarks, ROS nodes)
  local dir=$1; shift
  cmake -S . -B "$dir" "${release[@]}" "$@" >/dev/null
  cmake --build "$dir" -j"$jobs"
}

build_targets() {  # build_targets DIR "TARGET..." [extra cmake args...]: only those targets
  local dir=$1 targets=$2; shift 2
  cmake -S . -B "$dir" "${release[@]}" "$@" >/dev/null
  # shellcheck disable=SC2086  # the targets are words
  cmake --build "$dir" -j"$jobs" --target $targets
}

build_command() {  # build DIR: only the `echoplan` command, all the main job runs
  local dir=$1
  cmake -S . -B "$dir" "${release[@]}" >/dev/null
  cmake --build "$dir" -j"$jobs" --target echoplan
}

# The Python module of the normal build, installed where Debian's python3 imports it from, so
# `python3 -c "import echoplan"` works after setup (the sanitizer build has no module).
install_python() {  # install_python DIR
  local dir=$1
  [ "${ECHOPLAN_INSTALL_PYTHON:-1}" = 1 ] || return 0
  if [ ! -d "$dir/python/echoplan" ]; then
    echo "setup: no Python module in $dir (pybind11 not found at configure time)"
    return 0
  fi
  local sudo=()
  [ "$(id -u)" -eq 0 ] || sudo=(sudo)
  local prefix=${PYTHON_PREFIX:-/usr/local}
  "${sudo[@]}" cmake --install "$dir" --component python --strip --prefix "$prefix" >/dev/null
  echo "setup: installed the Python module echoplan under $prefix (python3 -c 'import echoplan')"
  # A python3 of the same version earlier on PATH (pyenv, a venv) does not look in Debian's
  # dist-packages: give it a copy too, so the README's `python3 -c "import echoplan"` works there.
  local other debian_version package
  other=$(command -v python3 || true)
  debian_version=$(/usr/bin/python3 -c 'import sys; print(sys.version_info[:2])')
  if [ -n "$other" ] && [ "$(readlink -f "$other")" != "$(readlink -f /usr/bin/python3)" ] &&
     [ "$("$other" -c 'import sys; print(sys.version_info[:2])' 2>/dev/null)" = "$debian_version" ]; then
    package=$(find "$prefix/lib" -path "*/dist-packages/echoplan" -type d | head -n 1)
    local site
    site=$("$other" -c 'import sysconfig; print(sysconfig.get_paths()["purelib"])')
    if [ -n "$package" ] && [ -n "$site" ] && [ "$(readlink -f "$site")" != "$(readlink -f "$(dirname "$package")")" ]; then
      "${sudo[@]}" rm -rf "$site/echoplan" && "${sudo[@]}" cp -r "$package" "$site/echoplan"
      echo "setup: and a copy for $other (another Python $debian_version on PATH) in $site"
    fi
  fi
}

case "$mode" in
  deps) install_deps ;;
  build) install_deps; use_compiler_cache; use_fast_linker; build "$build_dir"; install_python "$build_dir" ;;
  run)
    # Only the command: the tests and benchmarks the main job never runs wait for `test`.
    install_deps; use_compiler_cache; use_fast_linker; build_command "$build_dir"
    # The main job: the report's chapter 5 (experiments/chapter5.yaml) on all cores. Running it again
    # continues an interrupted campaign; a finished one is only re-reported.
    "$build_dir/echoplan" experiment --out results/chapter5
    echo "setup: the report is $here/results/chapter5/index.html"
    if [ "${ECHOPLAN_INSTALL_PYTHON:-1}" = 1 ]; then
      echo "setup: building the Python module"
      build_targets "$build_dir" echoplan_python
      install_python "$build_dir"
    fi
    ;;
  test)
    stage "installing dependencies"
    install_deps
    use_compiler_cache
    use_fast_linker
    # The cache's hit count at the end is this run's.
    if [ "${CMAKE_CXX_COMPILER_LAUNCHER:-}" = ccache ]; then ccache --zero-stats >/dev/null; fi
    if [ "${ECHOPLAN_CHECK_FORMAT:-1}" = 1 ]; then stage "format check"; scripts/check-format.sh; fi
    stage "normal build"
    build "$build_dir"
    stage "normal tests"
    ctest --test-dir "$build_dir" -j"$jobs" --output-on-failure
    stage "install check"
    scripts/check-install.sh "$build_dir"
    install_python "$build_dir"
    # The sanitizer build leaves the Python module out: an ASan extension only loads into a python3
    # started with libasan preloaded (cmake/EchoplanPython.cmake).
    stage "sanitizer build (ASan + UBSan; without the Python module)"
    # -O1: ASan's documented setting for speed (the suite ran 10x slower at -O0); Debug keeps asserts;
    # line tables (-g1) are all a sanitizer report needs, and compile 30% faster than -g. The
    # sanitizer builds are unity builds (CMake joins a target's files into batches): the same code in
    # fewer, larger compiles (the ASan build alone took about 30 of CI's minutes without). The normal
    # build above keeps one file per compile, which is what catches a file that forgets an include.
    build "$san_build_dir" -DECHOPLAN_SANITIZE=ON -DECHOPLAN_BUILD_BENCH=OFF -DCMAKE_BUILD_TYPE=Debug \
      -DCMAKE_CXX_FLAGS_DEBUG="-g1 -O1" -DCMAKE_UNITY_BUILD=ON
    stage "sanitizer tests"
    ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1 \
      ctest --test-dir "$san_build_dir" -j"$jobs" --output-on-failure
    stage "thread sanitizer build (${tsan_targets[*]}: the tests that start threads)"
    build_targets "$tsan_build_dir" "${tsan_targets[*]}" -DECHOPLAN_TSAN=ON -DECHOPLAN_BUILD_BENCH=OFF \
      -DECHOPLAN_BUILD_PYTHON=OFF -DCMAKE_UNITY_BUILD=ON
    stage "thread sanitizer tests"
    TSAN_OPTIONS=halt_on_error=1:second_deadlock_stack=1 \
      ctest --test-dir "$tsan_build_dir" -j"$jobs" -R "$tsan_tests" --output-on-failure
    # A smoke run on the committed corpus (docs/fuzzing.md has the long runs): a crash, hang or
    # sanitizer report in any target fails here.
    stage "fuzz targets (clang, libFuzzer), ${FUZZ_SECONDS:-5} s each"
    JOBS=$jobs scripts/fuzz.sh --all --seconds "${FUZZ_SECONDS:-5}"
    stage ""
    if [ "${CMAKE_CXX_COMPILER_LAUNCHER:-}" = ccache ]; then
      echo "setup: compiler cache: $(ccache --print-stats | awk -F'\t' '$1 == "direct_cache_hit" || $1 == "preprocessed_cache_hit" { hits += $2 } $1 == "cache_miss" { miss = $2 } END { printf "%d of %d compiles from the cache", hits, hits + miss }')"
    fi
    ;;
  -h|--help|help) sed -n '2,20p' "$0" | sed 's/^# \{0,1\}//' ;;
  *) echo "setup: unknown mode '$mode' (try: build, run, test, deps)" >&2; exit 2 ;;
esac
