#!/bin/sh
# `echoplan import oppt` end to end: an OPPT log written here (two runs of the reference's, the mug's
# "strike move_to_B" and the cup's "strike strike move_to_A") becomes steps.csv and trials.csv that
# `echoplan certify` reads; bad logs and mappings exit 2 naming the file, line or flag.
# Usage: import_cli_test.sh ECHOPLAN_BINARY SOURCE_DIR
. "$(dirname "$0")/cli_test_lib.sh"
problem=$src/problems/audio_objects.yaml
actions=4=slide,5=strike,6=move_to_A,7=move_to_B
observations=0=pringles_can,1=coffee_mug,2=plastic_cup,3=paper_base,5=none
objects=0=pringles_can,1=coffee_mug,2=plastic_cup,3=paper_base

# step T OBJECT ACTION OBSERVATION REWARD PARTICLE_OBJECTS...: one "t = " block of an OPPT log.
step() {
  t=$1 object=$2 action=$3 observation=$4 reward=$5
  shift 5
  echo "t = $t"
  echo "S: -2.89 1.45 -0.18 2.07 -0.31 0.63 -1.54 0.1 0 0 $object w: 1 END USER_DATA_BEGIN : 0 0 USER_DATA_END"
  echo "A: $action END"
  echo "O: $observation END"
  echo "IMMEDIATE_REWARD: $reward"
  echo "DISCOUNT_FACTOR: 1"
  echo "DISCOUNTED_REWARD: $reward"
  echo "PARTICLES BEGIN"
  for p in "$@"; do
    echo "p: -2.89 1.22 -0.15 1.81 -0.27 0.59 -1.52 0.002 -0.009 0.005 $p w: 0.001 END USER_DATA_BEGIN : 0 0 USER_DATA_END"
  done
  echo "PARTICLES END"
  echo "SOLVER_DATA_BEGIN"
  echo "NUM HISTORIES: 900"
  echo "SOLVER_DATA_END"
}
# trailer TOTAL STEPS: the run's end (the last step is written twice by OPPT, done by the caller).
trailer() {
  echo "Total discounted reward: $1"
  echo "Run successful: False"
  echo "Num steps: $2"
}
{
  echo "seed: 1234"
  echo "Run #1"
  step 0 1 5 1 -1 1 1 2
  step 1 1 7 5 10
  step 1 1 7 5 10
  trailer 8.9 2
  echo "Run #2"
  step 0 2 5 2 -1
  step 1 2 5 2 -1 2 2 2 1
  step 2 2 6 5 10
  step 2 2 6 5 10
  trailer 7.811 3
} >"$work/run.log"

"$bin" import oppt "$work/run.log" --actions $actions --observations $observations --objects $objects \
  --problem "$problem" --out "$work/imported" >"$work/out" 2>"$work/err" || { fail "import exited $?"; cat "$work/err"; }
grep -q "imported 2 runs (5 steps) from 1 log(s)" "$work/out" || { fail "summary lacks the runs and steps:"; cat "$work/out"; }
# Hand-computed: (8.9 + (-1 - 0.99 + 10 * 0.99^2)) / 2 = (8.9 + 7.811) / 2 = 8.3555; the logged totals agree.
grep -q "mean discounted reward: 8.3555 with the problem's discount 0.99 (logged: 8.3555)" "$work/out" \
  || { fail "summary's mean discounted reward:"; cat "$work/out"; }
grep -q "beliefs: 2 from logged particles, 2 the problem's initial belief, 1 the problem's exact belief" "$work/out" \
  || { fail "summary's belief sources:"; cat "$work/out"; }
expected_steps="trial,step,action,observation,particles_pringles_can,particles_coffee_mug,particles_plastic_cup,particles_paper_base,reward,episodes,heard_probability,heard_ebr_db
0,0,strike,coffee_mug,250,250,250,250,-1,900,,
0,1,move_to_B,none,0,2,1,0,10,900,,
1,0,strike,plastic_cup,250,250,250,250,-1,900,,
1,1,strike,plastic_cup,217,217,486,80,-1,900,,
1,2,move_to_A,none,0,1,3,0,10,900,,"
# Step 0 holds the problem's uniform prior as 1000 particles. Step 1 of run 2 follows an empty block:
# the exact belief after a strike heard as the cup, the strike table's plastic_cup column
# (0.3, 0.3, 0.67, 0.11) / 1.38, times 1000 particles: 217, 217, 486, 80.
[ "$(cat "$work/imported/steps.csv")" = "$expected_steps" ] || { fail "steps.csv:"; cat "$work/imported/steps.csv"; }
expected_trials="trial,true_state,believed_state,steps,n_slide,n_strike,n_move_to_A,n_move_to_B,discounted_reward,collision
0,coffee_mug,coffee_mug,2,0,1,0,1,8.9,0
1,plastic_cup,plastic_cup,3,0,2,1,0,7.811,0"
[ "$(cat "$work/imported/trials.csv")" = "$expected_trials" ] || { fail "trials.csv:"; cat "$work/imported/trials.csv"; }

"$bin" certify --problem "$problem" --steps "$work/imported/steps.csv" --root-expansions 1000 \
  >"$work/cert" 2>"$work/err" || { fail "certify exited $?"; cat "$work/err"; }
grep -q "(95% CI, 2 trials, 5 decisions)" "$work/cert" || { fail "certify's trial count:"; cat "$work/cert"; }

# Bad input: exit 2, naming the flag, or the file and line.
expect_input_error "unknown action name" "--actions: 'slid' is not one of the problem's names" \
  import oppt "$work/run.log" --actions 4=slid --observations $observations --objects $objects --problem "$problem" --out "$work/x"
expect_input_error "unmapped action code" "run.log:3: action code 5 has no --actions mapping" \
  import oppt "$work/run.log" --actions 7=move_to_B --observations $observations --objects $objects --problem "$problem" --out "$work/x"
expect_input_error "unknown observation name" "--observations: 'nothing'" \
  import oppt "$work/run.log" --actions $actions --observations 5=nothing --objects $objects --problem "$problem" --out "$work/x"
head -n 20 "$work/run.log" >"$work/cut.log"
expect_input_error "truncated log" "cut.log:20: run #1 (line 2) ends without 'Total discounted reward:'" \
  import oppt "$work/cut.log" --actions $actions --observations $observations --objects $objects --problem "$problem" --out "$work/x"
[ -e "$work/x" ] && fail "a refused import left an output folder"
expect_input_error "missing log" "nope.log: cannot open" \
  import oppt "$work/nope.log" --actions $actions --observations $observations --objects $objects --problem "$problem" --out "$work/x"
expect_input_error "no subcommand" "" import
finish import
