#!/bin/sh
# Lookalikes end to end (docs/feature-sets.md, "Objects unlike their class"), on the shipped
# synthetic feature set (experiments/data/synthetic_objects, two of its behaviours), novel objects
# sorted by group:
#   - a dataset campaign runs a planner arm without (`lookalike: false`: a dataset world's planner
#     plans with lookalikes unless told not to) and one with `lookalike: true`; each fold has a
#     problem of each kind beside its trials, both naming the lookalikes of the groups, with a
#     prior on them only in the lookalike arm's (its model's share);
#   - certify --campaign certifies each arm with its own fold problem;
#   - `lookalike` outside a dataset world is refused at its file and line, and the class-blind
#     `atypical` copies, which left the product, are an unknown key.
# Usage: lookalike_cli_test.sh ECHOPLAN_BINARY SOURCE_DIR
. "$(dirname "$0")/cli_test_lib.sh"
data="$work/data"
mkdir -p "$data"
cp -r "$src/experiments/data/synthetic_objects/groups.csv" "$src/experiments/data/synthetic_objects/shake" \
  "$src/experiments/data/synthetic_objects/tap" "$data/"

cat >"$work/lookalike.yaml" <<YAML
seed: 5
world: {type: dataset, data: $data, hold_out: object, groups: $data/groups.csv}
arms:
  - {name: plain, strategy: plan, lookalike: false}
  - {name: lookalike, strategy: plan, lookalike: true}
planner: {solver: abt, episodes: 500, max_steps: 100}
YAML
"$bin" experiment --config "$work/lookalike.yaml" --out "$work/lookalike" --workers 2 >"$work/lookalike.out" 2>&1 \
  || { fail "the campaign exited $?"; cat "$work/lookalike.out"; }

python3 - "$work/lookalike" <<'PY' || fail "the fold problems: see above"
import glob, os, sys, yaml
out = sys.argv[1]
bad = 0
folds = sorted(glob.glob(os.path.join(out, "folds", "*")))
if len(folds) < 2:
    print(f"{len(folds)} folds"); bad += 1
groups = ["group0", "group1", "group2"]
names = groups + [g + "~lookalike" for g in groups]
kinds = {"problem.yaml": None, "problem-lookalike.yaml": slice(3, 6)}
shares = {name: [] for name in kinds}
for fold in folds:
    for name, own in kinds.items():
        p = yaml.safe_load(open(os.path.join(fold, name)))
        if p["objects"] != names:
            print(f"{fold}/{name}: objects {p['objects']}"); bad += 1
            continue
        prior = [p["initial_belief"]["objects"][o] for o in p["objects"]]
        copies = slice(3, 6)
        if own is None and any(x != 0 for x in prior[copies]):
            print(f"{fold}/{name}: copies {names[copies]} have prior {prior[copies]}"); bad += 1
        if own is not None:
            share = sum(prior[own])
            shares[name].append(share)
            if not 0 <= share <= 0.5:
                print(f"{fold}/{name}: share {share}"); bad += 1
for name, found in shares.items():
    if kinds[name] is not None and not any(s > 0 for s in found):
        print(f"no fold's model found a share for {name}: {found}"); bad += 1
sys.exit(bad)
PY

"$bin" certify --campaign "$work/lookalike" --root-expansions 2000 --json >"$work/certify.json" 2>"$work/certify.err" \
  || { fail "certify --campaign exited $?"; cat "$work/certify.err"; }
python3 - "$work/certify.json" <<'PY' || fail "certify --campaign: see above"
import json, sys
entries = json.load(open(sys.argv[1]))["folds"]
bad = 0
for e in entries:
    name = {"lookalike": "problem-lookalike.yaml"}.get(e["arm"], "problem.yaml")
    if e["problem"] != f"folds/{e['fold']}/{name}":
        print(f"fold {e['fold']} arm {e['arm']} certified with {e['problem']}"); bad += 1
if {e["arm"] for e in entries} != {"plain", "lookalike"}:
    print("arms:", {e["arm"] for e in entries}); bad += 1
sys.exit(bad)
PY
# Progress on stderr: a line as each fold and arm is certified, counted against all of them.
folds_arms=$(python3 -c "import json, sys; print(len(json.load(open(sys.argv[1]))['folds']))" "$work/certify.json")
[ "$(grep -c "certified fold .*, arm .* ([0-9]* of $folds_arms, " "$work/certify.err")" = "$folds_arms" ] \
  || fail "certify --campaign did not report each of its $folds_arms folds x arms: $(cat "$work/certify.err")"
grep -q "certified fold 1, arm plain (1 of $folds_arms, " "$work/certify.err" \
  || fail "the first progress line is not fold 1's first arm: $(cat "$work/certify.err")"
grep -q '"interrupted": false' "$work/lookalike/certified/summary.json" \
  || fail "certified/summary.json does not say the certificates ran to the end"

# Only a dataset world's folds fit the share.
cat >"$work/simulated.yaml" <<YAML
arms:
  - {name: plan, problem: $src/problems/audio_objects.yaml, lookalike: true}
world: {type: simulated, problem: $src/problems/audio_objects.yaml}
trials:
  - {object: pringles_can, trials: 1}
planner: {solver: abt, episodes: 100}
YAML
expect_input_error "lookalike in a simulated world" "only for a dataset world" \
  experiment --config "$work/simulated.yaml" --out "$work/simulated"
grep -q "simulated.yaml:2" "$work/err" || fail "the refusal does not name the file and line: $(cat "$work/err")"
sed -i 's/lookalike: true/atypical: true/' "$work/simulated.yaml"
expect_input_error "the removed atypical option" "atypical" \
  experiment --config "$work/simulated.yaml" --out "$work/simulated"
grep -q "simulated.yaml:2" "$work/err" || fail "the refusal does not name the file and line: $(cat "$work/err")"

finish "lookalike"
