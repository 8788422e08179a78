#!/bin/sh
# Graded observations end to end (docs/perception.md, "Graded observations"), on the shipped synthetic
# feature set (experiments/data/synthetic_objects: 12 objects x 4 sessions, one performance of each
# behaviour per session; two behaviours of it here):
#   - a dataset campaign runs an arm that hears labels and one that hears graded observations on the
#     same sessions; each fold has a problem of each kind beside its trials, the graded arm's steps
#     are `<class>@<grade>`, and each performance's class is the one the labels arm heard for the
#     same recorded row (the grade refines the label, never changes it);
#   - certify --campaign certifies each arm with its own kind of fold problem;
#   - a graded arm that cannot hear grades is refused before any trial, with the reason.
# Usage: graded_cli_test.sh ECHOPLAN_BINARY SOURCE_DIR
. "$(dirname "$0")/cli_test_lib.sh"
# Two of the set's four behaviours (shake and tap), so the exact certificate of the graded arm (36 symbols
# per behaviour) stays quick.
data="$work/data"
mkdir -p "$data"
cp -r "$src/experiments/data/synthetic_objects/groups.csv" "$src/experiments/data/synthetic_objects/shake" \
  "$src/experiments/data/synthetic_objects/tap" "$data/"

cat >"$work/graded.yaml" <<YAML
seed: 5
world: {type: dataset, data: $data, hold_out: session, groups: $data/groups.csv}
arms:
  - {name: labels, strategy: plan}
  - {name: graded, strategy: plan, observations: graded}
planner: {solver: abt, episodes: 500, max_steps: 100}
YAML
"$bin" experiment --config "$work/graded.yaml" --out "$work/graded" --workers 2 >"$work/graded.out" 2>&1 \
  || { fail "the campaign exited $?"; cat "$work/graded.out"; }

for fold in 1 2 3 4; do
  for name in problem.yaml problem-graded.yaml; do
    [ -s "$work/graded/folds/$fold/$name" ] || fail "fold $fold has no $name"
  done
  grep -q "obj0@high" "$work/graded/folds/$fold/problem-graded.yaml" \
    || fail "fold $fold: problem-graded.yaml has no graded symbols"
  grep -q "@" "$work/graded/folds/$fold/problem.yaml" && fail "fold $fold: problem.yaml has graded symbols"
done

python3 - "$work/graded" <<'PY' || fail "the graded arm's steps: see above"
import csv, os, re, sys
out = sys.argv[1]
def uses(arm):
    """(object, session) -> action -> the observations heard at its 1st, 2nd, ... performance."""
    heard = {}
    for row in csv.DictReader(open(os.path.join(out, "arms", arm, "steps.csv"))):
        if row["observation"] == "none":
            continue
        heard.setdefault((row["object"], row["session"]), {}).setdefault(row["action"], []).append(
            row["observation"])
    return heard
labels, graded = uses("labels"), uses("graded")
bad = 0
grade = re.compile(r"^(obj[0-9]+)@(low|mid|high)$")
compared = 0
for trial, actions in graded.items():
    for action, observations in actions.items():
        for i, o in enumerate(observations):
            m = grade.match(o)
            if not m:
                print(f"{trial} {action}: '{o}' is not a graded symbol"); bad += 1
                continue
            heard = labels.get(trial, {}).get(action, [])
            if i < len(heard):
                compared += 1
                if heard[i] != m.group(1):
                    print(f"{trial} {action} #{i + 1}: graded heard {o}, labels heard {heard[i]}"); bad += 1
for trial, actions in labels.items():
    for action, observations in actions.items():
        if any("@" in o for o in observations):
            print(f"the labels arm heard a graded symbol in {trial}"); bad += 1
if compared < 40:
    print(f"only {compared} performances heard by both arms"); bad += 1
sys.exit(bad)
PY

"$bin" certify --campaign "$work/graded" --root-expansions 5000 --json >"$work/certify.json" 2>"$work/certify.err" \
  || { fail "certify --campaign exited $?"; cat "$work/certify.err"; }
python3 - "$work/certify.json" <<'PY' || fail "certify --campaign: see above"
import json, sys
entries = json.load(open(sys.argv[1]))["folds"]
bad = 0
want = {(f, a) for f in "1234" for a in ("labels", "graded")}
if {(e["fold"], e["arm"]) for e in entries} != want:
    print("folds x arms:", sorted((e["fold"], e["arm"]) for e in entries)); bad += 1
for e in entries:
    name = "problem-graded.yaml" if e["arm"] == "graded" else "problem.yaml"
    if e["problem"] != f"folds/{e['fold']}/{name}":
        print(f"fold {e['fold']} arm {e['arm']} certified with {e['problem']}"); bad += 1
sys.exit(bad)
PY

# A graded arm needs grades: a classifier's (calibrate: true) in a world that hears.
cat >"$work/uncalibrated.yaml" <<YAML
arms:
  - {name: graded, problem: $src/problems/audio_objects.yaml, observations: graded}
world: {type: simulated, problem: $src/problems/audio_objects.yaml}
trials:
  - {object: pringles_can, trials: 1}
planner: {solver: abt, episodes: 100}
YAML
expect_input_error "a graded arm without calibrate" "observations: graded needs calibrate: true" \
  experiment --config "$work/uncalibrated.yaml" --out "$work/uncalibrated"
grep -q "uncalibrated.yaml:2" "$work/err" || fail "the refusal does not name the file and line: $(cat "$work/err")"
sed -e 's/observations: graded}/observations: graded, calibrate: true}/' -e 's/type: simulated/type: model/' \
  "$work/uncalibrated.yaml" >"$work/model_world.yaml"
expect_input_error "a graded arm in a model world" "needs a world that hears" \
  experiment --config "$work/model_world.yaml" --out "$work/model_world"
sed 's/observations: graded/observations: soft/' "$work/uncalibrated.yaml" >"$work/unknown.yaml"
expect_input_error "an unknown kind of observations" "labels, graded" \
  experiment --config "$work/unknown.yaml" --out "$work/unknown"

finish "graded"
