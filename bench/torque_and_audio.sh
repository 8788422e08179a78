#!/bin/sh
# Torque beside sound in the simulated world (docs/BENCHMARKS.md, "Torque and sound"): the main
# job's four objects recorded by the simulator with every performance's joint torques and wrist
# force (docs/simulator.md, "Joint torques and wrist force"), then
#   1. `echoplan train` on the tree, cross-validated by session: each behaviour's held-out accuracy
#      per modality (audio, effort, force) and fused;
#   2. two dataset campaigns replaying every session, in the lab's quiet and through speech and
#      room noise at 0 dB event-to-background ratio (the torques hear no noise): the planner
#      hearing everything, audio alone and torque alone (effort and force), paired over the same
#      sessions, with the planner trained also in noise and information_gain beside them.
# Usage: bench/torque_and_audio.sh BUILD_DIR [SESSIONS] [EPISODES] [OUT]
#   SESSIONS  recordings per (object, behaviour), each its own session (default 24)
#   EPISODES  ABT episodes per step (default 2000)
set -eu
build=$1
sessions=${2:-24}
episodes=${3:-2000}
out=${4:-$(mktemp -d)}
bin="$build/echoplan"
speech=/usr/share/asterisk/sounds/en_US_f_Allison/digits  # scripts/setup.sh installs it
mkdir -p "$out"
"$bin" synth-recordings --per-pair "$sessions" --seed 1 -o "$out/tree" \
  --signals audio,effort,force --objects pringles_can,coffee_mug,plastic_cup,paper_base
echo "== held-out accuracy per behaviour and modality (train, by session)"
"$bin" train --data "$out/tree" --hold-out session --out "$out/model.json" 2>/dev/null \
  | sed -n '/held-out accuracy/,$p'

# campaign NAME WORLD_EXTRA: the arms over the tree, WORLD_EXTRA added to the world's map.
campaign() {
  cat >"$out/$1.yaml" <<YAML
seed: 1
world: {type: dataset, data: $out/tree, hold_out: session$2}
arms:
  - {name: plan_all, strategy: plan}
  - {name: plan_audio, strategy: plan, modalities: [audio]}
  - {name: plan_torque, strategy: plan, modalities: [effort, force]}
  - {name: plan_all_noise_trained, strategy: plan, trained_in_noise: true}
  - {name: information_gain, strategy: information_gain}
planner: {solver: abt, episodes: $episodes, max_steps: 100}
training_set: {noise: {sources: [$speech, room], ebr_db: "-6:24"}}
YAML
  "$bin" experiment --config "$out/$1.yaml" --out "$out/$1" --workers 2 >/dev/null 2>&1
  echo "== $1 ($out/$1/summary.txt)"
  cat "$out/$1/summary.txt"
}
campaign quiet ""
campaign noise_0db ", noise: {sources: [$speech, room], ebr_db: \"0\"}"
