#include "solvers/pomcp_solver.h"

namespace echoplan::solvers {

PomcpSolver::PomcpSolver(pomdp::ModelPtr model, SearchOptions options)
    : TreeSearchSolver(std::move(model), options, LeafUse::state_tree) {}

void PomcpSolver::run_episode(Rng& rng) {
  path_uses_ = path_uses_at_root();
  simulate(root(), sample_root_particle(rng), 0, rng);
}

double PomcpSolver::simulate(BeliefNode& node, pomdp::State state, int depth, Rng& rng) {
  const pomdp::Model& m = model();
  ++node.visits;
  if (depth > 0) node.particles.push_back(state);
  if (leaf_or_expand(node, depth)) {
    leaf_value().add(node.leaf,
                     LeafVisit{m, state, static_cast<std::size_t>(depth),
                               options().max_depth - depth, nullptr, &use_limits(), &path_uses_},
                     rng);
    return node.leaf.value();
  }
  const int a = select_action(node, path_uses_);
  use_limits().count(path_uses_, a);
  ActionNode& action = action_node(node, a);
  pomdp::StepResult step = m.step(state, a, rng);
  double sampled_return = step.reward;
  if (!step.terminal) {
    const std::size_t child = child_for(action, step.observation);
    sampled_return += m.spec().discount *
                      simulate(*action.children[child].node, std::move(step.next), depth + 1, rng);
  }
  // Running mean of the returns sampled through (node, a).
  ++node.action_visits;
  ++action.visits;
  action.value += (sampled_return - action.value) / static_cast<double>(action.visits);
  return sampled_return;
}

}  // namespace echoplan::solvers
