#include "solvers/abt_solver.h"

#include <algorithm>
#include <limits>

#include "common/error.h"

namespace echoplan::solvers {

namespace {
// Rollouts of the default policy each time an episode ends at a leaf: they cost a few belief
// updates each, far less than the episode that reached the leaf.
constexpr int kRolloutsPerLeafVisit = 1;

// The belief's marginal over discrete variable 0 as probabilities over the tabular states (for a
// tabular model, discrete[0] is the state index), absorbing states excluded.
std::vector<double> tabular_belief(const pomdp::Belief& belief, const pomdp::TabularModel& tables) {
  const std::vector<double> marginal = belief.discrete_marginal(0);
  std::vector<double> out(tables.num_states(), 0.0);
  double total = 0.0;
  for (int s = 0; s < tables.num_states() && s < static_cast<int>(marginal.size()); ++s)
    if (!tables.terminal(s)) total += out[s] = marginal[s];
  if (total > 0.0)
    for (double& p : out) p /= total;
  return out;
}
}  // namespace

AbtSolver::AbtSolver(pomdp::ModelPtr model, SearchOptions options)
    : TreeSearchSolver(std::move(model), options) {
  if (this->options().leaf.mode == LeafMode::policy) {
    const pomdp::TabularModel* tables = this->model().tabular();
    if (tables == nullptr)
      throw InputError(
          "the policy leaf value needs a discrete problem with tables; use --leaf "
          "lookahead for this one");
    policy_.emplace(*tables);
  }
}

void AbtSolver::reset(const pomdp::Belief& belief, Rng& rng) {
  TreeSearchSolver::reset(belief, rng);
  if (policy_) root_belief_ = tabular_belief(belief, *model().tabular());
}

void AbtSolver::update(int action, const pomdp::Observation& observation,
                       const pomdp::Belief& belief_after, Rng& rng) {
  TreeSearchSolver::update(action, observation, belief_after, rng);
  if (!policy_) return;
  // The tree's own exact belief follows the real step; the agent's belief (maybe a particle
  // filter) stands in only when the step is one the tables cannot explain.
  const bool sensing = !policy_->is_terminal(action) && observation.index >= 0;
  if (!sensing || policy_->update(root_belief_, action, observation.index, belief_scratch_) <= 0.0)
    root_belief_ = tabular_belief(belief_after, *model().tabular());
  else
    root_belief_.swap(belief_scratch_);
}

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

double AbtSolver::action_value(const BeliefNode& node, int a,
                               const std::vector<double>* belief) const {
  const ActionNode& action = *node.actions[a];
  const double gamma = model().spec().discount;
  if (!belief)
    return node.particle_reward_sums[a] / static_cast<double>(node.particles_evaluated) +
           gamma * action.future_sum / static_cast<double>(action.visits);
  // With the exact belief, the children are weighted by P(o | b, a) instead of by how often the
  // episodes happened to hear o (observations never heard yet share the weight of those that were,
  // in proportion); outcomes that end the episode count 0.
  double future = 0.0;
  if (!action.children.empty()) {
    double weighted = 0.0, seen = 0.0;
    for (const ObservationChild& child : action.children) {
      const double p = policy_->observation_probability(*belief, a, child.observation.index);
      weighted += p * child.node->value;
      seen += p;
    }
    if (seen > 0.0) future = policy_->live_probability(*belief, a) * weighted / seen;
  }
  return policy_->expected_reward(*belief, a) + gamma * future;
}

void AbtSolver::run_episode(Rng& rng) {
  const pomdp::Model& m = model();
  path_.clear();

  // The root's particle set changes on update (replenishment), so its Q values are refreshed here.
  BeliefNode& top = root();
  for (std::size_t a = 0; a < top.actions.size(); ++a)
    if (top.actions[a] && top.actions[a]->visits > 0)
      top.actions[a]->value =
          action_value(top, static_cast<int>(a), policy_ ? &root_belief_ : nullptr);

  // Walk down: the root's particle is already filed in the root; deeper nodes receive theirs.
  BeliefNode* node = &top;
  pomdp::State state = sample_root_particle(rng);
  if (policy_) path_beliefs_.assign(1, root_belief_);
  for (int depth = 0;; ++depth) {
    ++node->visits;
    if (depth > 0) {
      node->particles.push_back(state);
      evaluate_particle(*node, state, rng);
    }
    if (leaf_or_expand(*node, depth)) {
      if (policy_) {
        node->leaf.add_rollouts(*policy_, path_beliefs_.back(), options().max_depth - depth,
                                kRolloutsPerLeafVisit, rng);
      } else {
        node->leaf.add(options().leaf, m, state, options().max_depth - depth, rng, &one_step_each_);
      }
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
    if (policy_) {
      path_beliefs_.emplace_back();
      policy_->update(path_beliefs_[depth], a, action.children[child].observation.index,
                      path_beliefs_.back());
    }
    node = action.children[child].node.get();
    state = std::move(step.next);
  }

  // Back up along the path, deepest first: fold the child's new value into Q, then V = max_a Q.
  for (auto it = path_.rbegin(); it != path_.rend(); ++it) {
    BeliefNode& belief_node = *it->node;
    const std::size_t depth = static_cast<std::size_t>(path_.rend() - it) - 1;
    ActionNode& action = *belief_node.actions[it->action];
    if (it->child >= 0) {
      ObservationChild& child = action.children[static_cast<std::size_t>(it->child)];
      action.future_sum -= static_cast<double>(child.arrivals) * child.counted_value;
      ++child.arrivals;
      child.counted_value = child.node->value;
      action.future_sum += static_cast<double>(child.arrivals) * child.counted_value;
    }
    action.value = action_value(belief_node, it->action, policy_ ? &path_beliefs_[depth] : nullptr);
    double best = -std::numeric_limits<double>::infinity();
    for (const auto& candidate : belief_node.actions)
      if (candidate) best = std::max(best, candidate->value);
    belief_node.value = best;
  }
}

}  // namespace echoplan::solvers
