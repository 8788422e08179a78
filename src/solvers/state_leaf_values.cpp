#include "solvers/state_leaf_values.h"

namespace echoplan::solvers {

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

void LookaheadLeafValue::add(LeafEstimate& estimate, const LeafVisit& visit, Rng& rng) {
  const pomdp::Model& model = visit.model;
  const int actions = model.num_actions();
  const double gamma = model.spec().discount;
  double* sums = estimate.accumulate(static_cast<std::size_t>(actions), 1);
  for (int a = 0; a < actions; ++a) {
    const pomdp::StepResult step =
        visit.one_step_each ? (*visit.one_step_each)[a] : model.step(visit.state, a, rng);
    sums[a] += step.reward + (step.terminal ? 0.0 : gamma * model.heuristic_value(step.next));
  }
}

void HeuristicLeafValue::add(LeafEstimate& estimate, const LeafVisit& visit, Rng& /*rng*/) {
  estimate.accumulate(1, 1)[0] += visit.model.heuristic_value(visit.state);
}

void RolloutLeafValue::add(LeafEstimate& estimate, const LeafVisit& visit, Rng& rng) {
  estimate.accumulate(1, 1)[0] += random_rollout(visit.model, visit.state, visit.steps_left, rng);
}

}  // namespace echoplan::solvers
