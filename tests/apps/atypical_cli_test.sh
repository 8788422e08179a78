#!/bin/sh
# Objects unlike their class end to end (docs/feature-sets.md, "Objects unlike their class"), on the
# shipped synthetic feature set (experiments/data/synthetic_objects, two of its behaviours), novel
# objects sorted by group:
#   - a dataset campaign runs a planner arm without and one with `atypical: true`; each fold has a
#     problem of each kind beside its trials, both naming the atypical copies of the groups, the
#     plain arm's with no prior on them and the atypical arm's with its model's share;
#   - certify --campaign certifies each arm with its own fold problem;
#   - `atypical` outside a dataset world is refused at its file and line.
# Usage: atypical_cli_test.sh ECHOPLAN_BINARY SOURCE_DIR
. "$(dirname "$0")/cli_test_lib.sh"
data="$work/data"
mkdir -p "$data"
cp -r "$src/experiments/data/synthetic_objects/groups.csv" "$src/experiments/data/synthetic_objects/shake" \
  "$src/experiments/data/synthetic_objects/tap" "$data/"

cat >"$work/atypical.yaml" <<YAML
seed: 5
world: {type: dataset, data: $data, hold_out: object, groups: $data/groups.csv}
arms:
  - {name: plain, strategy: plan}
  - {name: atypical, strategy: plan, atypical: true}
planner: {solver: abt, episodes: 500, max_steps: 100}
YAML
"$bin" experiment --config "$work/atypical.yaml" --out "$work/atypical" --workers 2 >"$work/atypical.out" 2>&1 \
  || { fail "the campaign exited $?"; cat "$work/atypical.out"; }

python3 - "$work/atypical" <<'PY' || fail "the fold problems: see above"
import glob, os, sys, yaml
out = sys.argv[1]
bad = 0
folds = sorted(glob.glob(os.path.join(out, "folds", "*")))
if len(folds) < 2:
    print(f"{len(folds)} folds"); bad += 1
shares = []
for fold in folds:
    plain = yaml.safe_load(open(os.path.join(fold, "problem.yaml")))
    atypical = yaml.safe_load(open(os.path.join(fold, "problem-atypical.yaml")))
    for name, p in (("problem.yaml", plain), ("problem-atypical.yaml", atypical)):
        if p["objects"] != ["group0", "group1", "group2", "group0~atypical", "group1~atypical", "group2~atypical"]:
            print(f"{fold}/{name}: objects {p['objects']}"); bad += 1
    prior = lambda p: [p["initial_belief"]["objects"][o] for o in p["objects"]]
    if any(x != 0 for x in prior(plain)[3:]):
        print(f"{fold}/problem.yaml: the atypical copies have prior {prior(plain)[3:]}"); bad += 1
    share = sum(prior(atypical)[3:])
    shares.append(share)
    if not 0 <= share <= 0.5:
        print(f"{fold}/problem-atypical.yaml: atypical share {share}"); bad += 1
if not any(s > 0 for s in shares):
    print(f"no fold's model found atypical objects: shares {shares}"); bad += 1
sys.exit(bad)
PY

"$bin" certify --campaign "$work/atypical" --root-expansions 2000 --json >"$work/certify.json" 2>"$work/certify.err" \
  || { fail "certify --campaign exited $?"; cat "$work/certify.err"; }
python3 - "$work/certify.json" <<'PY' || fail "certify --campaign: see above"
import json, sys
entries = json.load(open(sys.argv[1]))["folds"]
bad = 0
for e in entries:
    name = "problem-atypical.yaml" if e["arm"] == "atypical" else "problem.yaml"
    if e["problem"] != f"folds/{e['fold']}/{name}":
        print(f"fold {e['fold']} arm {e['arm']} certified with {e['problem']}"); bad += 1
if {e["arm"] for e in entries} != {"plain", "atypical"}:
    print("arms:", {e["arm"] for e in entries}); bad += 1
sys.exit(bad)
PY

# Only a dataset world's folds fit the share.
cat >"$work/simulated.yaml" <<YAML
arms:
  - {name: plan, problem: $src/problems/audio_objects.yaml, atypical: true}
world: {type: simulated, problem: $src/problems/audio_objects.yaml}
trials:
  - {object: pringles_can, trials: 1}
planner: {solver: abt, episodes: 100}
YAML
expect_input_error "atypical in a simulated world" "only for a dataset world" \
  experiment --config "$work/simulated.yaml" --out "$work/simulated"
grep -q "simulated.yaml:2" "$work/err" || fail "the refusal does not name the file and line: $(cat "$work/err")"

finish "atypical"
