#include "solvers/belief_leaf_values.h"

#include <chrono>
#include <cmath>
#include <limits>

namespace echoplan::solvers {

namespace {
// Rollouts of the default policy each time an episode ends at a leaf: they cost a few belief
// updates each, far less than the episode that reached the leaf.
constexpr int kRolloutsPerLeafVisit = 1;
const UseCounts kNoUses;

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

PolicyLeafValue::PolicyLeafValue(pomdp::ModelPtr model)
    : model_(std::move(model)), policy_(*model_->tabular(), UseLimits(*model_)) {}

PolicyLeafValue::PolicyLeafValue(pomdp::ModelPtr model,
                                 std::shared_ptr<const IdentificationTables> tables)
    : model_(std::move(model)), policy_(std::move(tables)) {}

void PolicyLeafValue::add(LeafEstimate& estimate, const LeafVisit& visit, Rng& rng) {
  double* returns = estimate.accumulate(SensingPolicy::kThresholds, kRolloutsPerLeafVisit);
  for (int i = 0; i < kRolloutsPerLeafVisit; ++i)
    policy_.rollout(path_beliefs_[visit.depth], visit.uses ? *visit.uses : kNoUses,
                    visit.steps_left, rng, returns);
}

void PolicyLeafValue::reset(const pomdp::Belief& belief) {
  root_belief_ = tabular_belief(belief, *model_->tabular());
}

void PolicyLeafValue::follow(int action, const pomdp::Observation& observation,
                             const pomdp::Belief& belief_after) {
  // The tree's own exact belief follows the real step; the agent's belief (maybe a particle
  // filter) stands in only when the step is one the tables cannot explain.
  const bool sensing = !policy_.is_terminal(action) && observation.index >= 0;
  if (!sensing || policy_.update(root_belief_, action, observation.index, belief_scratch_) <= 0.0)
    root_belief_ = tabular_belief(belief_after, *model_->tabular());
  else
    root_belief_.swap(belief_scratch_);
}

void PolicyLeafValue::descend(std::size_t depth, int action, int observation) {
  path_beliefs_.resize(depth + 2);
  policy_.update(path_beliefs_[depth], action, observation, path_beliefs_.back());
}

ExactLeafValue::ExactLeafValue(pomdp::ModelPtr model, double exact_share, long offline_expansions)
    : ExactLeafValue(model, ExactBoundsGuide::read_tables(*model->tabular(), UseLimits(*model)),
                     exact_share, offline_expansions) {}

ExactLeafValue::ExactLeafValue(pomdp::ModelPtr model,
                               const std::shared_ptr<const IdentificationTables>& tables,
                               double exact_share, long offline_expansions)
    : PolicyLeafValue(std::move(model), tables),
      exact_share_(exact_share),
      guide_(tables, offline_expansions) {}

void ExactLeafValue::add(LeafEstimate& estimate, const LeafVisit& visit, Rng& rng) {
  if (!guided()) return PolicyLeafValue::add(estimate, visit, rng);
  estimate.set(guide_.leaf_value(path_nodes_[visit.depth]));
}

void ExactLeafValue::reset(const pomdp::Belief& belief) {
  PolicyLeafValue::reset(belief);
  guide_.reset(root_belief_);
  // The exact start belief rather than its particle sample's marginal.
  if (guided()) root_belief_ = guide_.root_belief();
}

void ExactLeafValue::follow(int action, const pomdp::Observation& observation,
                            const pomdp::Belief& belief_after) {
  guide_.follow(action, observation.index);
  PolicyLeafValue::follow(action, observation, belief_after);
}

void ExactLeafValue::start_episode() {
  PolicyLeafValue::start_episode();
  if (guided()) path_nodes_.assign(1, guide_.root());
}

void ExactLeafValue::descend(std::size_t depth, int action, int observation) {
  PolicyLeafValue::descend(depth, action, observation);
  if (!guided()) return;
  path_nodes_.resize(depth + 2);
  path_nodes_.back() = guide_.child(path_nodes_[depth], action, observation);
}

Budget ExactLeafValue::episode_budget(const Budget& budget) {
  if (!guided() || budget.amount <= 0) return budget;
  if (budget.kind == Budget::Kind::episodes) {
    const auto expansions = static_cast<long>(std::llround(exact_share_ * double(budget.amount)));
    if (expansions > 0)
      guide_.refine_root(RefineLimits{RefineLimits{}.target_gap, 0.0, expansions});
    return Budget::episodes(std::max<std::int64_t>(1, budget.amount - expansions));
  }
  const auto start = std::chrono::steady_clock::now();
  const double seconds = exact_share_ * double(budget.amount) / 1000.0;
  if (seconds > 0.0) guide_.refine_root(RefineLimits{RefineLimits{}.target_gap, seconds, 0});
  const double spent_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  // Whole milliseconds left for the episodes; none (the default share 1): one episode, which
  // keeps the tree's statistics alive without running over the step's time.
  const auto left = static_cast<std::int64_t>(double(budget.amount) - spent_ms);
  return left >= 1 ? Budget::milliseconds(left) : Budget::episodes(1);
}

double ExactLeafValue::clamp(std::size_t depth, double value) const {
  return guided() ? guide_.clamp(path_nodes_[depth], value) : value;
}

int ExactLeafValue::root_decision(int actions) const {
  if (!guided()) return -1;
  // The action whose lower bound on Q* is highest: the first step of the best plan the exact solver
  // has found here, whose value it guarantees. The episodes' own Q estimates are not consulted:
  // moved into the exact bounds they still decided between sensing actions by sampling noise and
  // lost far more (git history). When the bounds separate,
  // this is the action they prove optimal.
  int best = 0;
  double best_lower = -std::numeric_limits<double>::infinity();
  for (int a = 0; a < actions; ++a) {
    const double lower = guide_.action_bounds(a).lower;
    if (lower > best_lower) best = a, best_lower = lower;
  }
  return best;
}

}  // namespace echoplan::solvers
