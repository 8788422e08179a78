// Trials: plan, act in an environment, hear, update the belief, until the episode ends - many
// times.
//
// Each trial draws the hidden true state (from the model's initial belief, or with the object fixed
// when trials are run K per object), resets the environment, the belief and the solver, then loops
//   plan (solver.improve(budget)) -> act (environment.execute) -> belief.update -> solver.update
// until a terminal step, a collision or the step cap. Every random stream of trial t is derived
// from (seed, t), so a trial's outcome does not depend on the trials before it and an episode
// budget replays bit for bit.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "pomdp/belief.h"
#include "pomdp/environment.h"
#include "pomdp/model.h"
#include "solvers/solver.h"

namespace echoplan::experiment {

struct TrialOptions {
  int trials = 40;     // trials with the true state drawn from the initial belief (per_object == 0)
  int per_object = 0;  // > 0: this many trials for each value of discrete state variable 0
  solvers::Budget budget = solvers::Budget::episodes(1000);  // search per real step
  int max_steps = 100;  // a trial stops after this many steps even without a terminal step; >= 1
  std::uint64_t seed = 1;

  // Throws InputError naming the offending option.
  void validate() const;
  int total_trials(const pomdp::ModelSpec& spec) const;
};

// One real step of a trial. `belief` is the belief the action was chosen from: the marginal of
// discrete state variable 0 (for the seed's problem, the object), one probability per value.
struct StepRecord {
  int trial = 0;
  int step = 0;  // 0-based
  int action = 0;
  pomdp::Observation observation;
  std::vector<double> belief;
  double reward = 0.0;
  std::int64_t episodes = 0;  // search episodes run for this decision
  // The observation service's calibrated probability of the heard class; absent when the world
  // has no classifier (the model as the world samples its table).
  std::optional<double> heard_probability;
};

// One finished trial. `believed_state` is the most likely value of discrete variable 0 under the
// final belief (the one the last action was chosen from).
struct TrialRecord {
  int trial = 0;
  int true_state = 0;
  int believed_state = 0;
  int steps = 0;
  std::vector<int> action_counts;  // per action
  double discounted_reward = 0.0;  // sum_t gamma^t r_t
  bool collision = false;
  bool capped = false;  // stopped by max_steps rather than by a terminal step
};

// Receives results as they happen, so a log can be written trial by trial.
class TrialObserver {
 public:
  virtual ~TrialObserver() = default;
  // Called once per finished trial, with that trial's steps.
  virtual void trial_finished(const TrialRecord& trial, const std::vector<StepRecord>& steps) = 0;
};

// What a trial run needs; the callers own all of it.
struct TrialSetup {
  const pomdp::Model* model = nullptr;                      // the planning model (for names, discount)
  pomdp::Environment* environment = nullptr;                // where actions happen
  solvers::Solver* solver = nullptr;                        // reset at the start of every trial
  std::function<pomdp::BeliefPtr(Rng&)> make_belief;        // the initial belief of a trial
  const std::atomic<bool>* stop_requested = nullptr;        // optional: checked between steps
  // Optional: called after every step with its record and the belief after it, or nullptr when the
  // step ended the trial (no update follows a sorting action or a collision). For printing a trial as
  // it goes; trial_finished still gets every step.
  std::function<void(const StepRecord&, const pomdp::Belief*)> step_finished;
};

// One trial's results: the record and its steps.
struct TrialResult {
  TrialRecord record;
  std::vector<StepRecord> steps;
};

// Runs trial number `trial` alone: its random streams come from (options.seed, trial), so the
// result is the same whichever trials ran before it, in this process or another. `fixed_value` >= 0
// fixes discrete state variable 0 of the true state (the object); -1 draws it from the initial
// belief. Returns nothing when stopped before the trial ended (a cut-short trial is dropped whole).
std::optional<TrialResult> run_trial(const TrialSetup& setup, const TrialOptions& options,
                                     int trial, int fixed_value);

// Runs the trials, reporting each to `observer`. Returns the finished trials (fewer than asked when
// stopped); a trial cut short by a stop request is dropped whole.
std::vector<TrialRecord> run_trials(const TrialSetup& setup, const TrialOptions& options,
                                    TrialObserver& observer);

}  // namespace echoplan::experiment
