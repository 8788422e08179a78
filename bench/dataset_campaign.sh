#!/bin/sh
# The dataset campaign's speed target on a synthetic proxy (docs/BENCHMARKS.md, "Planning on
# recorded data at scale"): 100 objects x 9 behaviours whose informativeness differs (action
# scales 0.3 to 1.2), 20 categories of 5, five sessions per object, audio and haptic modalities;
# five arms (plan, all_actions, best_single, information_gain, random), ABT at EPISODES episodes,
# HOLD_OUT session or object, on WORKERS workers. Prints the wall and CPU time, peak memory and
# summary.txt's arm rows and paired differences.
# With ARMS=exact (environment): three arms instead, the planner with the exact leaf (plan_exact,
# listed first so the differences are against it), the default planner and information_gain.
# With SET=recorded (environment): the recorded-data stand-in instead of the proxy, with what
# makes real sets harder: two performances per session sharing its offset (session SD 0.6, so the
# table is tempered), a tenth of the objects like another group in every behaviour, and the
# planner sensing longer.
# With ARMS=graded (environment): four arms, plan and information_gain each hearing labels and
# grades (observations: graded), so grades are measured paired against labels; the planner is the
# default one (PLAN=plain: the plain one).
# With ARMS=unlike (environment): six arms, the five but random, the planner also planning with
# lookalikes (lookalike: true; plan_lookalike listed first), and information_gain also with
# lookalikes.
# With ARMS=unheard (environment): five arms, the planner counting a sensing action's unheard
# outcomes at their commit value (unheard: commit) with lookalikes (plan_commit_lookalike, listed
# first) and without, the default planner with lookalikes and without, and information_gain.
# With ARMS=commit (environment): two arms, plan_commit_lookalike against information_gain only
# (the pair the unheard comparison leaves open, in a fifth of its time).
# With ARMS=auto (environment): two arms, plan_auto_lookalike (unheard: auto: share or commit chosen
# by self-play on the folds' problems, experiment/unheard_choice.h) against information_gain; prints
# the choice (unheard.json). Where it chooses commit its trials are ARMS=commit's, seed for seed.
# With OBSERVATIONS=graded (environment): the five arms all hear grades.
# With STRATEGIES=lookalike (environment): the four fixed strategies of the five arms believe with
# lookalikes (`lookalike: true`).
# With PLAN=plain (environment): the planner of the five arms (and of ARMS=graded) counts unheard
# outcomes as shared and plans without lookalikes (unheard: share, lookalike: false): with HOLD_OUT
# object, as it did by default before a planner sorting novel objects defaulted to commit with
# lookalikes (with session it does so anyway); the other ARMS name their planners' settings.
# With COSTS=costed (environment): each behaviour priced (task.costs), from 0.5 for the least
# informative to 4.5 for the most, as published container studies price theirs: then information
# must be bought, and the arms are compared in cost-weighted reward.
# With SEED=N (environment, default 1): the feature set and the campaign drawn from seed N, so
# another seed gives independent trials (a new set of objects and sessions) to pool with seed 1's.
# Usage: [ARMS=exact|graded|unlike|unheard|commit|auto] [SET=recorded] [COSTS=costed] [OBSERVATIONS=graded]
#        [PLAN=plain] [SEED=N] bench/dataset_campaign.sh BUILD_DIR [EPISODES] [HOLD_OUT] [WORKERS] [OUT]
set -eu
# A misspelt switch would silently run another campaign than the one asked for.
check() {
  case " $3 " in *" $2 "*) ;; *)
    echo "dataset_campaign.sh: $1=$2 is not one of:$3 (or unset)" >&2
    exit 2
    ;;
  esac
}
check ARMS "${ARMS:-}" " exact graded unlike unheard commit auto"
check SET "${SET:-}" " recorded"
check COSTS "${COSTS:-}" " costed"
check OBSERVATIONS "${OBSERVATIONS:-}" " graded"
check PLAN "${PLAN:-}" " plain"
build=$1
episodes=${2:-20000}
hold_out=${3:-session}
seed=${SEED:-1}
case $seed in '' | *[!0-9]*)
  echo "dataset_campaign.sh: SEED=$seed is not a whole number" >&2
  exit 2
  ;;
esac
workers=${4:-2}
dir=$(mktemp -d)
out=${5:-$dir/campaign}
trap 'rm -rf "$dir"' EXIT
if [ "${SET:-}" = recorded ]; then
  set_options='--repeats 2 --session-sd 0.6 --lookalike-share 0.1'
else
  set_options='--session-sd 0.3'
fi
"$build/bench/make_feature_set" -o "$dir/fs100" --objects 100 --group-size 5 --sessions 5 \
  --actions press,grasp,lift,drop,poke,push,shake,tap,squeeze \
  --action-scales 0.3,0.4,0.5,0.6,0.7,0.8,0.9,1.0,1.2 --modality audio:8:1.5 \
  --modality haptic:4:1.0 --group-separation 1.0 --seed "$seed" $set_options
# The planner of the unheard and commit comparisons (one definition, so both run the same arm).
commit_lookalike='  - {name: plan_commit_lookalike, strategy: plan, unheard: commit, lookalike: true}'
# The planner without the novel-object defaults (the tables measured with it name it so).
plain=', unheard: share, lookalike: false'
# The planner of the five arms and of ARMS=graded: the default one, or with PLAN=plain the plain one.
planner=
[ "${PLAN:-}" = plain ] && planner=$plain
if [ "${ARMS:-}" = exact ]; then
  arms="  - {name: plan_exact, strategy: plan, leaf: exact$plain}
  - {name: plan, strategy: plan$plain}
  - {name: information_gain, strategy: information_gain}"
elif [ "${ARMS:-}" = graded ]; then
  arms="  - {name: plan_graded, strategy: plan, observations: graded$planner}
  - {name: plan, strategy: plan$planner}
  - {name: information_gain_graded, strategy: information_gain, observations: graded}
  - {name: information_gain, strategy: information_gain}"
elif [ "${ARMS:-}" = unheard ]; then
  arms="$commit_lookalike
  - {name: plan_lookalike, strategy: plan, lookalike: true, unheard: share}
  - {name: plan_commit, strategy: plan, unheard: commit, lookalike: false}
  - {name: plan, strategy: plan$plain}
  - {name: information_gain, strategy: information_gain}"
elif [ "${ARMS:-}" = commit ]; then
  arms="$commit_lookalike
  - {name: information_gain, strategy: information_gain}"
elif [ "${ARMS:-}" = auto ]; then
  arms='  - {name: plan_auto_lookalike, strategy: plan, unheard: auto, lookalike: true}
  - {name: information_gain, strategy: information_gain}'
elif [ "${ARMS:-}" = unlike ]; then
  arms="  - {name: plan_lookalike, strategy: plan, lookalike: true, unheard: share}
  - {name: plan, strategy: plan$plain}
  - {name: all_actions, strategy: all_actions}
  - {name: best_single, strategy: best_single}
  - {name: information_gain, strategy: information_gain}
  - {name: information_gain_lookalike, strategy: information_gain, lookalike: true}"
else
  heard=
  [ "${OBSERVATIONS:-}" = graded ] && heard=', observations: graded'
  fixed=$heard
  [ "${STRATEGIES:-}" = lookalike ] && fixed="$heard, lookalike: true"
  arms="  - {name: plan, strategy: plan$heard$planner}
  - {name: all_actions, strategy: all_actions$fixed}
  - {name: best_single, strategy: best_single$fixed}
  - {name: information_gain, strategy: information_gain$fixed}
  - {name: random, strategy: random$fixed}"
fi
costs=
if [ "${COSTS:-}" = costed ]; then
  costs='  costs: {press: 0.5, grasp: 1.0, lift: 1.5, drop: 2.0, poke: 2.5, push: 3.0, shake: 3.5, tap: 4.0, squeeze: 4.5}'
fi
cat >"$dir/campaign.yaml" <<YAML
seed: $seed
world: {type: dataset, data: $dir/fs100, hold_out: $hold_out, groups: $dir/fs100/groups.csv}
task:
  rewards: {right: 10, wrong: -100, sense: -1}
$costs
arms:
$arms
planner: {solver: abt, episodes: $episodes, max_steps: 100}
YAML
/usr/bin/time -f "%e s wall, %U s user, %M KB peak" -o "$dir/time" "$build/echoplan" experiment \
  --config "$dir/campaign.yaml" --out "$out" --workers "$workers" >/dev/null 2>&1
cat "$dir/time"
grep -E "^arm|^  all|minus" "$out/summary.txt"
grep "^time:" "$out/summary.txt" || true
if [ -f "$out/unheard.json" ]; then cat "$out/unheard.json"; fi
