#!/bin/sh
# The campaign's index.html renders in headless Chromium (Debian's `chromium`) from a file, without a
# server: the DOM holds the result tables and inlined figures, and the screenshot shows a styled table
# and coloured figures (screenshot_check.py). Exit 77 (skipped) when chromium is not installed.
# Usage: experiment_html_cli_test.sh ECHOPLAN_BINARY SOURCE_DIR
. "$(dirname "$0")/cli_test_lib.sh"
command -v chromium >/dev/null || { echo "chromium is not installed (scripts/setup.sh deps)"; exit 77; }

cat >"$work/campaign.yaml" <<YAML
seed: 2
arms:
  - {name: hand_tuned, problem: $src/problems/audio_objects.yaml}
world: {type: model, problem: $src/problems/audio_objects.yaml}
training_set: {recordings_per_pair: 1}
trials:
  - {object: pringles_can, trials: 3}
  - {object: paper_base, trials: 3}
planner: {solver: abt, episodes: 500, max_steps: 30}
reference: $src/experiments/chapter5_reference.yaml
YAML
"$bin" experiment --config "$work/campaign.yaml" --out "$work/run" >/dev/null 2>&1 || fail "experiment exited $?"

# The flags known to work here (no sandbox as root, no network, a fresh profile).
chrome() {
  chromium --headless --no-sandbox --disable-gpu --disable-quic --no-first-run --disable-background-networking \
    --disable-component-update --disable-sync --user-data-dir="$work/profile" "$@" 2>>"$work/chromium.err"
}
chrome --dump-dom "file://$work/run/index.html" >"$work/dom.html"
for text in "Results and the report" "Every trial" "Every decision" "<table" "pringles_can" "paper_base"; do
  grep -q "$text" "$work/dom.html" || fail "the rendered DOM lacks '$text'"
done
images=$(grep -o 'src="data:image/png;base64,' "$work/dom.html" | wc -l)
[ "$images" -ge 4 ] || fail "the rendered DOM holds $images inlined figures, expected 4 (templates, 2 belief, confusion)"
grep -q 'src="http\|href="http\|<script' "$work/dom.html" && fail "the page reaches outside itself"

chrome --screenshot="$work/page.png" --window-size=1300,1600 --hide-scrollbars "file://$work/run/index.html" >/dev/null
[ -s "$work/page.png" ] || { fail "no screenshot"; cat "$work/chromium.err"; }
/usr/bin/python3 "$src/tests/apps/screenshot_check.py" "$work/page.png" || fail "the screenshot check failed"

finish "HTML"
