#include "solvers/abt_solver.h"

#include <algorithm>
#include <limits>

namespace echoplan::solvers {

AbtSolver::AbtSolver(pomdp::ModelPtr model, SearchOptions options)
    : TreeSearchSolver(std::move(model), options) {}

void AbtSolver::run_episode(Rng& rng) {
  const pomdp::Model& m = model();
  const double gamma = m.spec().discount;
  path_.clear();

  // Walk down: the root's particle is already filed in the root; deeper nodes receive theirs.
  BeliefNode* node = &root();
  pomdp::State state = sample_root_particle(rng);
  for (int depth = 0;; ++depth) {
    ++node->visits;
    if (depth > 0) node->particles.push_back(state);
    if (visit_as_leaf(*node, depth)) {
      node->leaf.add(options().leaf, m, state, options().max_depth - depth, rng);
      node->value = node->leaf.value();
      break;
    }
    const int a = select_action(*node);
    ActionNode& action = action_node(*node, a);
    pomdp::StepResult step = m.step(state, a, rng);
    ++node->action_visits;
    ++action.visits;
    action.reward_sum += step.reward;
    if (step.terminal) {
      path_.push_back({node, &action, -1});
      break;
    }
    const std::size_t child = child_for(action, step.observation);
    path_.push_back({node, &action, static_cast<std::ptrdiff_t>(child)});
    node = action.children[child].node.get();
    state = std::move(step.next);
  }

  // Back up along the path, deepest first: fold the child's new value into Q, then V = max_a Q.
  for (auto it = path_.rbegin(); it != path_.rend(); ++it) {
    ActionNode& action = *it->action;
    if (it->child >= 0) {
      ObservationChild& child = action.children[static_cast<std::size_t>(it->child)];
      action.future_sum -= static_cast<double>(child.arrivals) * child.counted_value;
      ++child.arrivals;
      child.counted_value = child.node->value;
      action.future_sum += static_cast<double>(child.arrivals) * child.counted_value;
    }
    action.value = (action.reward_sum + gamma * action.future_sum) / static_cast<double>(action.visits);
    double best = -std::numeric_limits<double>::infinity();
    for (const auto& candidate : it->node->actions)
      if (candidate) best = std::max(best, candidate->value);
    it->node->value = best;
  }
}

}  // namespace echoplan::solvers
