#include "solvers/abt_solver.h"

#include <algorithm>
#include <limits>

namespace echoplan::solvers {

AbtSolver::AbtSolver(pomdp::ModelPtr model, SearchOptions options)
    : TreeSearchSolver(std::move(model), options) {}

void AbtSolver::evaluate_particle(BeliefNode& node, const pomdp::State& state, Rng& rng) {
  const pomdp::Model& m = model();
  const int actions = m.num_actions();
  one_step_each_.clear();
  for (int a = 0; a < actions; ++a) one_step_each_.push_back(m.step(state, a, rng));
  node.particle_reward_sums.resize(actions, 0.0);
  for (int a = 0; a < actions; ++a) node.particle_reward_sums[a] += one_step_each_[a].reward;
  ++node.particles_evaluated;
}

void AbtSolver::root_particle_added(BeliefNode& root, const pomdp::State& state, Rng& rng) {
  evaluate_particle(root, state, rng);
}

double AbtSolver::action_value(const BeliefNode& node, int a) const {
  const ActionNode& action = *node.actions[a];
  return node.particle_reward_sums[a] / static_cast<double>(node.particles_evaluated) +
         model().spec().discount * action.future_sum / static_cast<double>(action.visits);
}

void AbtSolver::run_episode(Rng& rng) {
  const pomdp::Model& m = model();
  path_.clear();

  // The root's particle set changes on update (replenishment), so its Q values are refreshed here.
  BeliefNode& top = root();
  for (std::size_t a = 0; a < top.actions.size(); ++a)
    if (top.actions[a] && top.actions[a]->visits > 0)
      top.actions[a]->value = action_value(top, static_cast<int>(a));

  // Walk down: the root's particle is already filed in the root; deeper nodes receive theirs.
  BeliefNode* node = &top;
  pomdp::State state = sample_root_particle(rng);
  for (int depth = 0;; ++depth) {
    ++node->visits;
    if (depth > 0) {
      node->particles.push_back(state);
      evaluate_particle(*node, state, rng);
    }
    if (visit_as_leaf(*node, depth)) {
      node->leaf.add(options().leaf, m, state, options().max_depth - depth, rng, &one_step_each_);
      node->value = node->leaf.value();
      break;
    }
    const int a = select_action(*node);
    ActionNode& action = action_node(*node, a);
    pomdp::StepResult step = m.step(state, a, rng);
    ++node->action_visits;
    ++action.visits;
    if (step.terminal) {
      path_.push_back({node, a, -1});
      break;
    }
    const std::size_t child = child_for(action, step.observation);
    path_.push_back({node, a, static_cast<std::ptrdiff_t>(child)});
    node = action.children[child].node.get();
    state = std::move(step.next);
  }

  // Back up along the path, deepest first: fold the child's new value into Q, then V = max_a Q.
  for (auto it = path_.rbegin(); it != path_.rend(); ++it) {
    BeliefNode& belief_node = *it->node;
    ActionNode& action = *belief_node.actions[it->action];
    if (it->child >= 0) {
      ObservationChild& child = action.children[static_cast<std::size_t>(it->child)];
      action.future_sum -= static_cast<double>(child.arrivals) * child.counted_value;
      ++child.arrivals;
      child.counted_value = child.node->value;
      action.future_sum += static_cast<double>(child.arrivals) * child.counted_value;
    }
    action.value = action_value(belief_node, it->action);
    double best = -std::numeric_limits<double>::infinity();
    for (const auto& candidate : belief_node.actions)
      if (candidate) best = std::max(best, candidate->value);
    belief_node.value = best;
  }
}

}  // namespace echoplan::solvers
