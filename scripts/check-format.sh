#!/usr/bin/env bash
# Layout check: fails (exit 1) listing every tracked C++ file that clang-format 14 with the repository's
# .clang-format would change. Fix them with: clang-format-14 -i FILE...
#
#   scripts/check-format.sh
#
# `scripts/setup.sh test` (hence .ci/run) runs it when ECHOPLAN_CHECK_FORMAT=1. It is off by default
# until the one whole-tree formatting commit lands (the lead switches the default then).
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$here"

# Debian's clang-format 14: other versions lay out some constructs differently.
formatter=""
for candidate in clang-format-14 clang-format; do
  if command -v "$candidate" >/dev/null && "$candidate" --version | grep -q "version 14\."; then
    formatter=$candidate
    break
  fi
done
if [ -z "$formatter" ]; then
  echo "check-format: clang-format 14 not found (Debian package clang-format-14; scripts/setup.sh deps)" >&2
  exit 2
fi

if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  mapfile -t files < <(git ls-files -- '*.cpp' '*.h' '*.hpp' '*.cc')
else
  mapfile -t files < <(find apps bench fuzz python src tests \( -name '*.cpp' -o -name '*.h' \) | sort)
fi

mapfile -t unformatted < <(
  printf '%s\0' "${files[@]}" |
    xargs -0 -n 50 "$formatter" --style=file --dry-run --Werror 2>&1 |
    sed -n 's/^\(.*\):[0-9]*:[0-9]*: error: code should be clang-formatted.*/\1/p' | sort -u
)
if [ ${#unformatted[@]} -gt 0 ]; then
  echo "check-format: ${#unformatted[@]} of ${#files[@]} C++ files differ from $formatter's layout:" >&2
  printf '  %s\n' "${unformatted[@]}" >&2
  echo "check-format: fix with: $formatter -i FILE..." >&2
  exit 1
fi
echo "check-format: all ${#files[@]} C++ files match $formatter's layout"
