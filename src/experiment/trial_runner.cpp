#include "experiment/trial_runner.h"

#include <algorithm>
#include <stdexcept>

#include "common/error.h"

namespace echoplan::experiment {

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

}  // namespace

std::optional<TrialResult> run_trial(const TrialSetup& setup, const TrialOptions& options, int t,
                                     int fixed_value) {
  if (!setup.model || !setup.environment || !setup.solver || !setup.make_belief)
    throw std::invalid_argument("run_trial: incomplete TrialSetup");
  const pomdp::Model& model = *setup.model;
  const double gamma = model.spec().discount;
  auto stopped = [&] { return setup.stop_requested && setup.stop_requested->load(); };

  Rng truth_rng(derive_seed(options.seed, {static_cast<std::uint64_t>(t), truth}));
  Rng env_rng(derive_seed(options.seed, {static_cast<std::uint64_t>(t), environment}));
  Rng belief_rng(derive_seed(options.seed, {static_cast<std::uint64_t>(t), belief}));
  Rng planner_rng(derive_seed(options.seed, {static_cast<std::uint64_t>(t), planner}));

  const pomdp::State truth_state = draw_true_state(model, fixed_value, truth_rng);
  setup.environment->reset(truth_state, env_rng);
  pomdp::BeliefPtr belief = setup.make_belief(belief_rng);
  setup.solver->reset(*belief, planner_rng);

  TrialResult result;
  TrialRecord& record = result.record;
  record.trial = t;
  record.true_state = truth_state.discrete.empty() ? 0 : truth_state.discrete[0];
  record.action_counts.assign(model.num_actions(), 0);
  double weight = 1.0;
  for (int step = 0;; ++step) {
    if (stopped()) return std::nullopt;
    StepRecord s;
    s.trial = t;
    s.step = step;
    s.belief = belief->discrete_marginal(0);
    setup.solver->improve(options.budget, planner_rng);
    s.episodes = setup.solver->stats().episodes_last;
    s.action = setup.solver->best_action();
    const pomdp::Outcome outcome = setup.environment->execute(s.action, env_rng);
    s.observation = outcome.observation;
    s.reward = outcome.reward;
    s.heard_probability = outcome.heard_probability;
    result.steps.push_back(s);

    record.believed_state = most_likely(s.belief);
    ++record.action_counts[s.action];
    record.discounted_reward += weight * outcome.reward;
    weight *= gamma;
    record.steps = step + 1;
    if (outcome.terminal || outcome.collision) {
      record.collision = outcome.collision;
      if (setup.step_finished) setup.step_finished(s, nullptr);
      break;
    }
    belief->update(s.action, outcome.observation, belief_rng);
    if (setup.step_finished) setup.step_finished(s, belief.get());
    if (record.steps >= options.max_steps) {
      // The belief after the last step is the final one.
      record.believed_state = most_likely(belief->discrete_marginal(0));
      record.capped = true;
      break;
    }
    setup.solver->update(s.action, outcome.observation, *belief, planner_rng);
  }
  return result;
}

std::vector<TrialRecord> run_trials(const TrialSetup& setup, const TrialOptions& options,
                                    TrialObserver& observer) {
  if (!setup.model || !setup.environment || !setup.solver || !setup.make_belief)
    throw std::invalid_argument("run_trials: incomplete TrialSetup");
  options.validate();
  const int total = options.total_trials(setup.model->spec());
  std::vector<TrialRecord> finished;
  for (int t = 0; t < total; ++t) {
    const int fixed_value = options.per_object > 0 ? t / options.per_object : -1;
    std::optional<TrialResult> result = run_trial(setup, options, t, fixed_value);
    if (!result) break;
    observer.trial_finished(result->record, result->steps);
    finished.push_back(std::move(result->record));
  }
  return finished;
}

}  // namespace echoplan::experiment
