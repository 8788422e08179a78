// One trial: plan, act in a world, hear, update the belief, until the episode ends.
//
// A trial draws the hidden true state (from the model's initial belief, or with the object fixed),
// resets the world, the belief and the solver, then loops
//   plan (solver.improve(budget)) -> act (world.execute) -> belief.update -> solver.update
// until a terminal step, a collision or the step cap. A step with a fault (loop/step_fault.h) is
// logged as a warning naming the trial and the step; when its observation was skipped, the
// belief is not updated. Every random stream of trial t is derived
// from (seed, t), so a trial's outcome does not depend on the trials before it and an episode
// budget replays bit for bit.
//
// loop/loop.h assembles the parts (problem, world, planner, belief) from a checked specification;
// this file only runs them.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "loop/trial_record.h"
#include "loop/world.h"
#include "pomdp/belief.h"
#include "pomdp/model.h"
#include "solvers/solver.h"

namespace echoplan::loop {

struct TrialOptions {
  int trials = 40;     // trials with the true state drawn from the initial belief (per_object == 0)
  int per_object = 0;  // > 0: this many trials for each value of discrete state variable 0
  solvers::Budget budget = solvers::Budget::episodes(1000);  // search per real step
  int max_steps = 100;  // a trial stops after this many steps even without a terminal step; >= 1
  std::uint64_t seed = 1;

  // Throws InputError naming the offending option.
  void validate() const;
  int total_trials(const pomdp::ModelSpec& spec) const;
  // The object of trial `t` when trials are run per object; -1 (drawn) otherwise.
  int object_of_trial(int t) const { return per_object > 0 ? t / per_object : -1; }
};

// One real step with everything it produced: the decision and what the planner was told (`record`),
// the belief after the update (none when the step ended the trial: no update follows a sorting
// action or a collision), and the robot's part in a world with a robot.
struct Step {
  StepRecord record;
  std::optional<std::vector<double>> belief_after;
  std::optional<RobotStep> robot;
  bool terminal = false;
};

// One trial's results: the record and its steps.
struct Trial {
  TrialRecord record;
  std::vector<Step> steps;
};

// What a trial runs on; the caller (a Loop) owns all of it.
struct TrialParts {
  const pomdp::Model* model = nullptr;  // the planning model (for the discount and sizes)
  World* world = nullptr;
  solvers::Solver* solver = nullptr;                  // reset at the start of every trial
  std::function<pomdp::BeliefPtr(Rng&)> make_belief;  // the initial belief of a trial
};

// Called after every step, as it happens (to print or log a trial as it goes).
using StepFn = std::function<void(const Step&)>;

// Runs trial number `trial`: its random streams come from (options.seed, trial), so the result is
// the same whichever trials ran before it, in this process or another. `fixed_value` >= 0 fixes
// discrete state variable 0 of the true state (the object); -1 draws it from the initial belief.
// Returns nothing when `stop` was set before the trial ended (a cut-short trial is dropped whole).
std::optional<Trial> run_trial(const TrialParts& parts, const TrialOptions& options, int trial,
                               int fixed_value, const StepFn& on_step = {},
                               const std::atomic<bool>* stop = nullptr);

}  // namespace echoplan::loop
