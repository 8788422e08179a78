#include "solvers/leaf_value.h"

#include <algorithm>
#include <limits>
#include <stdexcept>

#include "common/error.h"
#include "solvers/identification_solver.h"

namespace echoplan::solvers {

LeafMode parse_leaf_mode(const std::string& text) {
  if (text == "policy") return LeafMode::policy;
  if (text == "exact") return LeafMode::exact;
  if (text == "exact-offline") return LeafMode::exact_offline;
  if (text == "lookahead") return LeafMode::lookahead;
  if (text == "heuristic") return LeafMode::heuristic;
  if (text == "rollout") return LeafMode::rollout;
  throw InputError("leaf value '" + text +
                   "' is not one of policy, exact, exact-offline, lookahead, heuristic, rollout");
}

const char* leaf_mode_name(LeafMode mode) {
  switch (mode) {
    case LeafMode::policy:
      return "policy";
    case LeafMode::exact:
      return "exact";
    case LeafMode::exact_offline:
      return "exact-offline";
    case LeafMode::lookahead:
      return "lookahead";
    case LeafMode::heuristic:
      return "heuristic";
    case LeafMode::rollout:
      return "rollout";
  }
  return "?";
}

LeafMode default_leaf_mode(const std::string& solver, const pomdp::Model& model) {
  const pomdp::TabularModel* tables = model.tabular();
  if (solver == "abt" && tables != nullptr && !identification_shape_problem(*tables))
    return LeafMode::policy;
  return LeafMode::lookahead;
}

namespace {

double random_rollout(const pomdp::Model& model, pomdp::State state, int steps_left, Rng& rng) {
  const double gamma = model.spec().discount;
  const int actions = model.num_actions();
  double total = 0.0;
  double weight = 1.0;
  for (int k = 0; k < steps_left; ++k) {
    const int action = static_cast<int>(uniform01(rng) * actions);
    pomdp::StepResult step = model.step(state, action, rng);
    total += weight * step.reward;
    weight *= gamma;
    if (step.terminal) return total;
    state = std::move(step.next);
  }
  // Cut off by the depth limit: the model's heuristic stands in for the rest.
  return total + weight * model.heuristic_value(state);
}

}  // namespace

void LeafEstimate::add(const LeafOptions& options, const pomdp::Model& model,
                       const pomdp::State& state, int steps_left, Rng& rng,
                       const std::vector<pomdp::StepResult>* one_step_each) {
  if (options.mode == LeafMode::policy || options.mode == LeafMode::exact ||
      options.mode == LeafMode::exact_offline)
    throw std::logic_error(std::string("LeafEstimate: the ") + leaf_mode_name(options.mode) +
                           " leaf value is not added particle by particle");
  ++count_;
  switch (options.mode) {
    case LeafMode::policy:
    case LeafMode::exact:
    case LeafMode::exact_offline:
      return;  // refused above
    case LeafMode::heuristic:
      sums_.resize(1, 0.0);
      sums_[0] += model.heuristic_value(state);
      return;
    case LeafMode::rollout:
      sums_.resize(1, 0.0);
      sums_[0] += random_rollout(model, state, steps_left, rng);
      return;
    case LeafMode::lookahead: {
      const int actions = model.num_actions();
      const double gamma = model.spec().discount;
      sums_.resize(actions, 0.0);
      for (int a = 0; a < actions; ++a) {
        const pomdp::StepResult step =
            one_step_each ? (*one_step_each)[a] : model.step(state, a, rng);
        sums_[a] += step.reward + (step.terminal ? 0.0 : gamma * model.heuristic_value(step.next));
      }
      return;
    }
  }
}

void LeafEstimate::add_rollouts(const SensingPolicy& policy, const std::vector<double>& belief,
                                int steps_left, int rollouts, Rng& rng) {
  sums_.resize(SensingPolicy::kThresholds, 0.0);
  for (int i = 0; i < rollouts; ++i) policy.rollout(belief, steps_left, rng, sums_.data());
  count_ += rollouts;
}

double LeafEstimate::value() const {
  if (count_ == 0) return 0.0;
  // One accumulator is a plain mean; several are per-action (or per-threshold) means, of which the
  // best counts.
  return *std::max_element(sums_.begin(), sums_.end()) / count_;
}

void LeafEstimate::remove(const std::vector<double>& contribution) {
  if (count_ == 0 || contribution.size() != sums_.size())
    throw std::logic_error("LeafEstimate::remove(): not a contribution of this estimate");
  for (std::size_t i = 0; i < sums_.size(); ++i) sums_[i] -= contribution[i];
  --count_;
}

void LeafEstimate::set(double value) {
  sums_.assign(1, value);
  count_ = 1;
}

void LeafEstimate::release() {
  sums_.clear();
  sums_.shrink_to_fit();
}

}  // namespace echoplan::solvers
