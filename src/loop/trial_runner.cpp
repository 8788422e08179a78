#include "loop/trial_runner.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <stdexcept>

#include "common/error.h"

namespace echoplan::loop {

void TrialOptions::validate() const {
  if (trials < 1 && per_object < 1) throw InputError("--trials must be >= 1");
  if (per_object < 0) throw InputError("--per-object must be >= 0");
  if (budget.amount < 1)
    throw InputError("the search budget (--episodes / --step-ms) must be >= 1");
  if (max_steps < 1) throw InputError("--max-steps must be >= 1");
}

int TrialOptions::total_trials(const pomdp::ModelSpec& spec) const {
  if (per_object == 0) return trials;
  const auto& values = spec.state.discrete_value_names;
  if (values.empty()) throw InputError("--per-object needs a model with a discrete state variable");
  return per_object * static_cast<int>(values[0].size());
}

namespace {

// Independent streams of one trial.
enum Stream : std::uint64_t { truth = 1, environment = 2, belief = 3, planner = 4 };

// The trial's true state: from the initial belief, conditioned on discrete variable 0 == `value`
// when value >= 0 (rejection sampling; the initial belief must give the value some probability).
pomdp::State draw_true_state(const pomdp::Model& model, int value, Rng& rng) {
  constexpr int kAttempts = 100000;
  for (int i = 0; i < kAttempts; ++i) {
    pomdp::State state = model.sample_initial_state(rng);
    if (value < 0 || (!state.discrete.empty() && state.discrete[0] == value)) return state;
  }
  throw InputError("--per-object: the initial belief never produced " +
                   model.spec().state.discrete_value_names[0][value] + " in " +
                   std::to_string(kAttempts) + " draws");
}

int most_likely(const std::vector<double>& marginal) {
  return static_cast<int>(std::max_element(marginal.begin(), marginal.end()) - marginal.begin());
}

// Adds step `s` to the trial's record.
void count_step(TrialRecord& record, const StepRecord& s, double& weight, double gamma) {
  record.believed_state = most_likely(s.belief);
  ++record.action_counts[s.action];
  record.discounted_reward += weight * s.reward;
  weight *= gamma;
  record.steps = s.step + 1;
}

// A solver must never choose an action the trial has used up (pomdp::Model::max_uses) or whose
// prerequisites it has not taken (pomdp::Model::prerequisites): it would ask the world for a
// performance it does not have, or one the robot cannot do yet. A logic error, not bad input.
void check_available(const pomdp::Model& model, const TrialRecord& record, int action) {
  const auto& names = model.spec().action_names;
  const int limit = model.max_uses(action);
  if (limit > 0 && record.action_counts[action] >= limit)
    throw std::logic_error("the solver chose '" + names[action] + "' in trial " +
                           std::to_string(record.trial) + " after its " + std::to_string(limit) +
                           " allowed use" + (limit == 1 ? "" : "s") + " were spent");
  for (int r : model.prerequisites(action))
    if (record.action_counts[r] == 0)
      throw std::logic_error("the solver chose '" + names[action] + "' in trial " +
                             std::to_string(record.trial) + " before '" + names[r] +
                             "', which it requires");
}

}  // namespace

std::optional<Trial> run_trial(const TrialParts& parts, const TrialOptions& options, int t,
                               int fixed_value, const StepFn& on_step,
                               const std::atomic<bool>* stop) {
  if (!parts.model || !parts.world || !parts.solver || !parts.make_belief)
    throw std::invalid_argument("run_trial: incomplete TrialParts");
  const pomdp::Model& model = *parts.model;
  const double gamma = model.spec().discount;
  const auto stream = [&](Stream s) {
    return Rng(derive_seed(options.seed, {static_cast<std::uint64_t>(t), s}));
  };
  Rng truth_rng = stream(truth), world_rng = stream(environment);
  Rng belief_rng = stream(belief), planner_rng = stream(planner);

  const pomdp::State truth_state = draw_true_state(model, fixed_value, truth_rng);
  parts.world->reset(truth_state, world_rng);
  pomdp::BeliefPtr belief = parts.make_belief(belief_rng);
  parts.solver->reset(*belief, planner_rng);

  Trial result;
  TrialRecord& record = result.record;
  record.trial = t;
  record.true_state = truth_state.discrete.empty() ? 0 : truth_state.discrete[0];
  record.action_counts.assign(model.num_actions(), 0);
  double weight = 1.0;
  for (int step = 0;; ++step) {
    if (stop && stop->load()) return std::nullopt;
    Step& s = result.steps.emplace_back();
    StepRecord& r = s.record;
    r.trial = t;
    r.step = step;
    r.belief = belief->discrete_marginal(0);
    parts.solver->improve(options.budget, planner_rng);
    r.episodes = parts.solver->stats().episodes_last;
    r.action = parts.solver->best_action();
    check_available(model, record, r.action);
    WorldStep happened = parts.world->execute(r.action, world_rng);
    const pomdp::Outcome& outcome = happened.outcome;
    r.observation = outcome.observation;
    r.reward = outcome.reward;
    r.heard_probability = outcome.heard_probability;
    r.heard_ebr_db = outcome.heard_ebr_db;
    s.robot = std::move(happened.robot);
    if (s.robot && !s.robot->report.surface.empty()) record.surface = s.robot->report.surface;
    s.terminal = outcome.terminal || outcome.collision;
    count_step(record, r, weight, gamma);
    if (s.robot && s.robot->fault)
      spdlog::warn(fault_text(t, step, model.spec().action_names[r.action], *s.robot->fault));
    if (s.terminal) {
      record.collision = outcome.collision;
      if (on_step) on_step(s);
      break;
    }
    // A step whose observation was skipped (a fault, loop/step_fault.h) teaches the belief nothing:
    // it stays as it was, and the planner re-roots on it below (its tree never saw "none" after a
    // sensing action, so it plans afresh from the belief).
    if (!(s.robot && s.robot->observation_skipped()))
      belief->update(r.action, outcome.observation, belief_rng);
    s.belief_after = belief->discrete_marginal(0);
    if (on_step) on_step(s);
    if (record.steps >= options.max_steps) {
      // The belief after the last step is the final one.
      record.believed_state = most_likely(*s.belief_after);
      record.capped = true;
      break;
    }
    parts.solver->update(r.action, outcome.observation, *belief, planner_rng);
  }
  return result;
}

}  // namespace echoplan::loop
