#!/bin/sh
# Behaviour costs and certified dataset campaigns end to end, on the shipped synthetic feature set
# (experiments/data/synthetic_objects: press, shake, tap, squeeze, each telling the objects apart
# better than the last; 12 objects x 4 sessions, one performance of each behaviour per session).
#   - Unpriced, best_single repeats squeeze (the most accurate). With squeeze at cost 200 (two
#     wrong sorts' worth) and the others at sense = -1, no strategy that weighs costs performs it,
#     all_actions pays 1 + 1 + 1 + 200 = 203 per trial, and every arm's mean cost in summary.json
#     is the mean of its trials' action counts x costs, recomputed here from trials.csv.
#   - The campaign writes each fold's problem (with the costs) beside the fold's trials; certify
#     --campaign certifies each fold's arms with it, and agrees with certify --problem --steps on
#     the same files.
#   - task.requires (squeeze after a press and a tap): every arm keeps the order, the folds' problems
#     carry it, and a prerequisite the data lacks or a circle is refused.
#   - train --costs: the problem it writes carries the costs; bad rows are refused at file:line.
#   - train --requires: the problem carries the prerequisites; bad ones are refused before the fit.
# Usage: costs_cli_test.sh ECHOPLAN_BINARY SOURCE_DIR
. "$(dirname "$0")/cli_test_lib.sh"
data="$src/experiments/data/synthetic_objects"

sensing_reward() {  # BEHAVIOUR PROBLEM: its reward.sensing entry, as a number
  awk -v b="$1:" '/^reward:/ {r = 1} r && $1 == "sensing:" {s = 1; next} s && $1 == b {print $2 + 0; exit}' "$2"
}

campaign() {  # NAME ARMS TASK: a dataset campaign over the shipped data into $work/NAME
  cat >"$work/$1.yaml" <<YAML
seed: 3
world: {type: dataset, data: $data, hold_out: session, groups: $data/groups.csv}
task: $3
arms: [$2]
planner: {solver: abt, episodes: 500, max_steps: 100}
YAML
  "$bin" experiment --config "$work/$1.yaml" --out "$work/$1" --workers 2 >"$work/$1.out" 2>&1 \
    || { fail "campaign $1 exited $?"; cat "$work/$1.out"; }
}

# Unpriced: best_single's most accurate behaviour is squeeze.
campaign unpriced "{name: best_single, strategy: best_single}" "{rewards: {sense: -1}}"
squeezes=$(awk -F, 'NR == 1 {for (i = 1; i <= NF; i++) if ($i == "n_squeeze") c = i} NR > 1 {s += $c} END {print s}' \
  "$work/unpriced/arms/best_single/trials.csv")
[ "$squeezes" = 48 ] || fail "unpriced best_single should squeeze once in each of 48 trials, squeezed $squeezes"

campaign priced "{name: plan, strategy: plan}, {name: all_actions, strategy: all_actions}, \
{name: best_single, strategy: best_single}, {name: information_gain, strategy: information_gain}" \
  "{rewards: {right: 10, wrong: -100, sense: -1}, costs: {squeeze: 200}}"
python3 - "$work/priced" <<'PY' || fail "priced campaign: see above"
import csv, json, os, sys
out = sys.argv[1]
costs = {"press": 1.0, "shake": 1.0, "tap": 1.0, "squeeze": 200.0}
summary = json.load(open(os.path.join(out, "summary.json")))
bad = 0
for row in summary["results"]:
    if row["objects"] != "all":
        continue
    arm = row["arm"]
    trials = list(csv.DictReader(open(os.path.join(out, "arms", arm, "trials.csv"))))
    expected = sum(sum(int(t["n_" + b]) * c for b, c in costs.items()) for t in trials) / len(trials)
    if abs(row.get("mean_cost", -1) - expected) > 1e-9:
        print(f"{arm}: mean_cost {row.get('mean_cost')} but trials.csv gives {expected}"); bad += 1
    squeezed = sum(int(t["n_squeeze"]) for t in trials)
    if arm == "all_actions" and abs(expected - 203.0) > 1e-9:
        print(f"all_actions should pay 203 per trial, paid {expected}"); bad += 1
    if arm in ("plan", "best_single", "information_gain") and squeezed:
        print(f"{arm} squeezed {squeezed} times at cost 200"); bad += 1
sys.exit(bad)
PY
grep -q "cost" "$work/priced/summary.txt" || fail "summary.txt has no cost column"
[ -s "$work/priced/figures/accuracy_vs_cost.svg" ] || fail "no accuracy-against-cost figure"
grep -q "accuracy_vs_cost" "$work/priced/index.html" || fail "the page does not show accuracy against cost"
grep -q "<th>mean cost</th>" "$work/priced/index.html" || fail "the page's table has no mean cost"

# Each fold (one held-out session of every object) beside its problem, which carries the costs.
for fold in 1 2 3 4; do
  problem="$work/priced/folds/$fold/problem.yaml"
  [ -s "$problem" ] || { fail "fold $fold: no problem.yaml"; continue; }
  [ "$(sensing_reward squeeze "$problem")" = -200 ] || fail "fold $fold: the problem does not price squeeze at 200"
  [ "$(sensing_reward press "$problem")" = -1 ] || fail "fold $fold: press is not at sense = -1"
  session=s$((fold - 1))
  others=$(awk -F, -v s="$session" 'NR == 1 {for (i = 1; i <= NF; i++) if ($i == "session") c = i}
    NR > 1 && $c != s {n++} END {print n + 0}' "$work/priced/folds/$fold/arms/plan/trials.csv")
  rows=$(($(wc -l <"$work/priced/folds/$fold/arms/plan/trials.csv") - 1))
  [ "$rows" -eq 12 ] && [ "$others" -eq 0 ] \
    || fail "fold $fold: expected the 12 trials of session $session, got $rows rows, $others of other sessions"
done

# certify --campaign: a line per fold and arm; the same figures as certifying the fold's files alone.
"$bin" certify --campaign "$work/priced" --root-expansions 20000 >"$work/certify.out" 2>&1 \
  || { fail "certify --campaign exited $?"; cat "$work/certify.out"; }
"$bin" certify --problem "$work/priced/folds/2/problem.yaml" --steps "$work/priced/folds/2/arms/plan/steps.csv" \
  --root-expansions 20000 --json >"$work/alone.json" 2>/dev/null || fail "certify of fold 2 alone exited $?"
python3 - "$work/priced/certified/summary.json" "$work/alone.json" <<'PY' || fail "certified summary: see above"
import json, sys
summary, alone = json.load(open(sys.argv[1])), json.load(open(sys.argv[2]))
entries = summary["folds"]
bad = 0
pairs = {(e["fold"], e["arm"]) for e in entries}
want = {(f, a) for f in "1234" for a in ("all_actions", "best_single", "information_gain", "plan")}
if pairs != want:
    print("folds x arms:", sorted(pairs)); bad += 1
for e in entries:
    vstar = (e["vstar_lower"] + e["vstar_upper"]) / 2
    loose = max(e["vstar_upper"] - e["vstar_lower"], e["bound_gap_mean"]) / abs(vstar)
    if e["trials"] != 12 or e["tight"] != (loose <= 0.01):
        print("entry", e); bad += 1
    if e["tight"]:
        share = 1 - e["regret_mean"] / abs(vstar)  # below 1 by the regret's share of abs(V*)
        if e["share_of_vstar"] is None or abs(e["share_of_vstar"] - share) > 1e-9:
            print("tight entry without its share", e); bad += 1
    elif e["share_of_vstar"] is not None or "share_range" not in e:
        print("loose entry states a share", e); bad += 1
for f in "1234":
    # all_actions squeezes at 200 in every trial: it loses far more than the planner.
    by_arm = {e["arm"]: e for e in entries if e["fold"] == f}
    if not by_arm["all_actions"]["regret_mean"] > by_arm["plan"]["regret_mean"] + 100:
        print(f"fold {f}: all_actions regret {by_arm['all_actions']['regret_mean']} vs plan {by_arm['plan']['regret_mean']}"); bad += 1
two = [e for e in entries if e["fold"] == "2" and e["arm"] == "plan"][0]
for key in ("vstar_lower", "vstar_upper", "regret_mean", "regret_ci95"):
    if abs(two[key] - alone[key]) > 1e-9:
        print(f"fold 2 plan {key}: campaign {two[key]}, alone {alone[key]}"); bad += 1
sys.exit(bad)
PY
grep -q "plan" "$work/certify.out" || fail "certify --campaign printed no plan line"
expect_input_error "certify --campaign of a campaign without folds" "has no folds/ folder" \
  certify --campaign "$work"
expect_input_error "certify --campaign with --problem" "drop --problem" \
  certify --campaign "$work/priced" --problem "$work/priced/folds/1/problem.yaml"

# A task cost for a behaviour the data does not have names the campaign file.
sed 's/costs: {squeeze: 200}/costs: {squish: 200}/' "$work/priced.yaml" >"$work/squish.yaml"
expect_input_error "a cost for an unknown behaviour" "squish.yaml: task.costs: 'squish' is not a behaviour" \
  experiment --config "$work/squish.yaml" --out "$work/squish"
sed 's/costs: {squeeze: 200}/costs: {squeeze: -2}/' "$work/priced.yaml" >"$work/negative.yaml"
expect_input_error "a negative cost" "negative.yaml:3" experiment --config "$work/negative.yaml" --out "$work/negative"

# task.requires: squeeze opens only after a press and a tap. Every arm keeps that order in every
# trial (steps.csv), and each fold's problem carries it (actions.requires).
campaign gated "{name: plan, strategy: plan}, {name: all_actions, strategy: all_actions}, \
{name: best_single, strategy: best_single}" "{requires: {squeeze: [press, tap]}}"
python3 - "$work/gated" <<'PY' || fail "gated campaign: see above"
import csv, os, sys
out, bad = sys.argv[1], 0
for arm in ("plan", "all_actions", "best_single"):
    done, squeezes = {}, 0
    for row in csv.DictReader(open(os.path.join(out, "arms", arm, "steps.csv"))):
        trial = (row["trial"], row["object"], row["session"])
        seen = done.setdefault(trial, set())
        if row["action"] == "squeeze":
            squeezes += 1
            if not {"press", "tap"} <= seen:
                print(f"{arm}: trial {trial} squeezed after only {sorted(seen)}"); bad += 1
        seen.add(row["action"])
    if arm == "all_actions" and squeezes != 48:
        print(f"all_actions should squeeze once in each of 48 trials, squeezed {squeezes}"); bad += 1
    if not squeezes:  # the order above is checked only where squeeze was done
        print(f"{arm} never squeezed"); bad += 1
sys.exit(bad)
PY
grep -A2 "^  requires:" "$work/gated/folds/1/problem.yaml" | grep -q "squeeze: \[press, tap\]" \
  || fail "fold 1's problem does not carry squeeze's prerequisites"
sed 's/requires: {squeeze: \[press, tap\]}/requires: {squeeze: [press, squish]}/' "$work/gated.yaml" >"$work/squish_first.yaml"
expect_input_error "a prerequisite the data does not have" \
  "squish_first.yaml: task.requires: 'squish' is not a behaviour" \
  experiment --config "$work/squish_first.yaml" --out "$work/squish_first"
sed 's/requires: {squeeze: \[press, tap\]}/requires: {squeeze: [tap], tap: [squeeze]}/' "$work/gated.yaml" >"$work/circle.yaml"
expect_input_error "prerequisites in a circle" "task.requires goes round in a circle (squeeze -> tap -> squeeze)" \
  experiment --config "$work/circle.yaml" --out "$work/circle"

# train --costs: the problem carries them; mistakes name the file and line.
printf 'behaviour,cost\nsqueeze,4.5\ntap,0.5\n' >"$work/costs.csv"
"$bin" train --data "$data" --costs "$work/costs.csv" --problem-out "$work/trained.yaml" >"$work/train.out" 2>&1 \
  || { fail "train --costs exited $?"; cat "$work/train.out"; }
[ "$(sensing_reward squeeze "$work/trained.yaml")" = -4.5 ] || fail "train --costs: squeeze is not at -4.5"
[ "$(sensing_reward tap "$work/trained.yaml")" = -0.5 ] || fail "train --costs: tap is not at -0.5"
[ "$(sensing_reward press "$work/trained.yaml")" = -1 ] || fail "train --costs: press is not at --reward-sense"
refused_costs() {  # NAME CONTENT MESSAGE: train --costs with a file NAME.csv holding CONTENT fails
  printf "$2" >"$work/$1.csv"
  expect_input_error "train --costs, $1" "$1.csv:$3" \
    train --data "$data" --costs "$work/$1.csv" --problem-out "$work/x.yaml"
}
refused_costs unknown 'behaviour,cost\nsqueeze,4.5\nsquish,1\n' "3: 'squish' is not a behaviour of the data"
refused_costs nan 'behaviour,cost\nsqueeze,lots\n' "2: the cost of 'squeeze' is 'lots', not a number"
refused_costs negative 'behaviour,cost\ntap,-1\n' "2: the cost of 'tap' is '-1'"
refused_costs header 'action,price\ntap,1\n' "1: the header must be 'behaviour,cost'"
refused_costs twice 'behaviour,cost\ntap,1\ntap,2\n' "3: 'tap' is priced twice"
refused_costs ragged 'behaviour,cost\ntap,1,2\n' "2: 3 cells"

# train --requires: the problem it writes carries the prerequisites (as the campaign's folds do), and
# the planner it feeds keeps the order; mistakes are refused before the fit.
"$bin" train --data "$data" --requires squeeze=press,tap --requires shake=squeeze --problem-out "$work/gated_trained.yaml" \
  >"$work/train_req.out" 2>&1 || { fail "train --requires exited $?"; cat "$work/train_req.out"; }
grep -A3 "^  requires:" "$work/gated_trained.yaml" | grep -q "squeeze: \[press, tap\]" \
  && grep -A3 "^  requires:" "$work/gated_trained.yaml" | grep -q "shake: \[squeeze\]" \
  || { fail "train --requires: the problem lacks the prerequisites"; grep -A3 requires "$work/gated_trained.yaml"; }
"$bin" trials --problem "$work/gated_trained.yaml" --solver all_actions --trials 3 --seed 1 --out "$work/gated_trials" \
  >/dev/null 2>&1 || fail "trials on train --requires' problem exited $?"
/usr/bin/python3 - "$work/gated_trials/steps.csv" <<'PY' || fail "all_actions broke train --requires' order"
import csv, sys
done, bad = {}, 0
for row in csv.DictReader(open(sys.argv[1])):
    seen = done.setdefault(row["trial"], set())
    a = row["action"]
    if a == "squeeze" and not {"press", "tap"} <= seen: bad += 1
    if a == "shake" and "squeeze" not in seen: bad += 1
    seen.add(a)
sys.exit(1 if bad or not any("shake" in s for s in done.values()) else 0)
PY
expect_input_error "train --requires, an unknown behaviour" "--requires: 'squish' is not a behaviour of the data" \
  train --data "$data" --requires squeeze=squish --problem-out "$work/x.yaml"
expect_input_error "train --requires, a circle" "--requires goes round in a circle" \
  train --data "$data" --requires squeeze=tap --requires tap=squeeze --problem-out "$work/x.yaml"
expect_input_error "train --requires, no '='" "--requires squeeze: expected BEHAVIOUR=BEHAVIOUR" \
  train --data "$data" --requires squeeze --problem-out "$work/x.yaml"
expect_input_error "train --requires, itself" "squeeze cannot require itself" \
  train --data "$data" --requires squeeze=squeeze --problem-out "$work/x.yaml"
expect_input_error "train --requires with a base problem" "--requires orders the behaviours of the data's own problem" \
  train --data "$data" --requires squeeze=tap --problem-base "$src/problems/audio_objects.yaml" --problem-out "$work/x.yaml"
finish "costs and certified-campaign"
