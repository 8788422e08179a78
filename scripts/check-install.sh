#!/usr/bin/env bash
# Checks that echoplan installs like a library people build on: `cmake --install` of a build into a
# temporary prefix, then tests/install/ (a small project of someone else's) configured with
# find_package(echoplan), built and run against it, and the installed binary run from elsewhere.
#
#   scripts/check-install.sh [BUILD_DIR]     (default: build; it must be built already)
#
# Called by `scripts/setup.sh test` (hence by .ci/run). Exit status 0 when every check passes.
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build_dir=$(cd "${1:-$here/build}" && pwd)
prefix=$(mktemp -d)
trap 'rm -rf "$prefix"' EXIT

echo "check-install: installing $build_dir into $prefix"
cmake --install "$build_dir" --prefix "$prefix/usr" >/dev/null

# The package must not point back into the source or build tree: a consumer sees only the prefix.
if grep -rlF -e "$here/src" -e "$build_dir" "$prefix/usr/lib/cmake/echoplan"; then
  echo "check-install: FAIL: the installed CMake package refers to the source or build tree" >&2
  exit 1
fi

echo "check-install: building tests/install against the installed package"
cmake -S "$here/tests/install" -B "$prefix/consumer" -DCMAKE_PREFIX_PATH="$prefix/usr" \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build "$prefix/consumer" >/dev/null
"$prefix/consumer/link_every_module"
"$prefix/consumer/consumer" "$prefix/usr/share/echoplan/problems/tiger.pomdp"

# The installed binary finds its shipped data relative to itself, also after the prefix moves, and
# does not carry the source tree's path in its constant data.
if readelf -p .rodata "$prefix/usr/bin/echoplan" | grep -F "$here" >/dev/null; then
  echo "check-install: FAIL: bin/echoplan holds a path into the source tree" >&2
  exit 1
fi
mv "$prefix/usr" "$prefix/moved"
(cd "$prefix" && "$prefix/moved/bin/echoplan" synth --object coffee_mug --action strike --seed 1 \
  -o "$prefix/strike.wav" >/dev/null)
[ -s "$prefix/strike.wav" ] || { echo "check-install: FAIL: the installed binary wrote no recording" >&2; exit 1; }

# The Python module (when the build has one) imports from the moved prefix with Debian's python3
# and finds the shipped data in its own package, not through the build or source tree.
package=$(find "$prefix/moved" -path "*/dist-packages/echoplan/__init__.py" 2>/dev/null | head -n 1)
if [ -n "$package" ]; then
  echo "check-install: importing the installed Python module"
  (cd "$prefix" && env -u ECHOPLAN_DATA_DIR PYTHONPATH="$(dirname "$(dirname "$package")")" /usr/bin/python3 -c '
import echoplan
problem = echoplan.load_problem(echoplan.shipped_file("problems/audio_objects.yaml"))
trials = echoplan.run_trials(problem, trials=2, episodes=100, seed=1)
assert len(trials) == 2 and echoplan.__file__.startswith("'"$prefix/moved"'"), echoplan.__file__
print("check-install: echoplan", echoplan.__version__, "planned 2 trials from", echoplan.__file__)
') || { echo "check-install: FAIL: the installed Python module does not work" >&2; exit 1; }
fi
echo "check-install: all checks passed"
