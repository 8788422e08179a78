#include "solvers/state_leaf_values.h"

#include <limits>
#include <stdexcept>

namespace echoplan::solvers {

namespace {

// A uniformly random action among those `limits` still allow after `uses` (counted in).
int random_allowed_action(const UseLimits& limits, UseCounts& uses, int actions, Rng& rng) {
  std::vector<int> allowed;
  for (int a = 0; a < actions; ++a)
    if (limits.allows(uses, a)) allowed.push_back(a);
  if (allowed.empty()) throw std::logic_error("the use limits leave no action to take");
  const int action = allowed[static_cast<std::size_t>(uniform01(rng) * double(allowed.size()))];
  limits.count(uses, action);
  return action;
}

// Uniformly random play; with use limits (`visit.limits`), uniform over the actions still
// available, counted from the uses at the leaf. Without limits the draws are those of plain
// uniform play over all actions.
double random_rollout(const LeafVisit& visit, Rng& rng) {
  const pomdp::Model& model = visit.model;
  const bool limited = visit.limits && visit.limits->any();
  UseCounts uses = limited && visit.uses ? *visit.uses : UseCounts{};
  pomdp::State state = visit.state;
  const double gamma = model.spec().discount;
  const int actions = model.num_actions();
  double total = 0.0;
  double weight = 1.0;
  for (int k = 0; k < visit.steps_left; ++k) {
    const int action = limited ? random_allowed_action(*visit.limits, uses, actions, rng)
                               : static_cast<int>(uniform01(rng) * actions);
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
    if (!visit.allows(a)) {  // used up at this node: never the best next step
      sums[a] = -std::numeric_limits<double>::infinity();
      continue;
    }
    const pomdp::StepResult step =
        visit.one_step_each ? (*visit.one_step_each)[a] : model.step(visit.state, a, rng);
    sums[a] += step.reward + (step.terminal ? 0.0 : gamma * model.heuristic_value(step.next));
  }
}

void HeuristicLeafValue::add(LeafEstimate& estimate, const LeafVisit& visit, Rng& /*rng*/) {
  estimate.accumulate(1, 1)[0] += visit.model.heuristic_value(visit.state);
}

void RolloutLeafValue::add(LeafEstimate& estimate, const LeafVisit& visit, Rng& rng) {
  estimate.accumulate(1, 1)[0] += random_rollout(visit, rng);
}

}  // namespace echoplan::solvers
