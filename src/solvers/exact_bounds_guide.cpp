#include "solvers/exact_bounds_guide.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "common/error.h"

namespace echoplan::solvers {

namespace {
// A reset belief this far (total variation) from the problem's start belief is another belief, not
// a particle sample of it (1,000 particles over 4 objects: about 0.02).
constexpr double kStartBeliefTolerance = 0.1;
// A leaf's lookahead: one expansion, to no particular gap.
constexpr RefineLimits kLeafLookahead{1e-12, 0.0, 1};
// A trial's solver stops refining (its bounds stay valid) at this many nodes, about 600 MB on the
// report's problem: a trial that never becomes sure (100 steps of 20,000 expansions) would
// otherwise grow towards the solver's own 2 GB cap in every worker. The measured trials stay far
// below it (7 steps of 20 ms: about 100,000 nodes; the offline solve's 200,000 expansions: about
// 800,000).
constexpr std::size_t kMaxNodesPerTrial = 3000000;

IdentificationOptions planner_solver_options() {
  IdentificationOptions options;
  options.max_nodes = kMaxNodesPerTrial;
  return options;
}
}  // namespace

std::shared_ptr<const IdentificationTables> ExactBoundsGuide::read_tables(
    const pomdp::TabularModel& model, const UseLimits& limits) {
  if (auto why = identification_shape_problem(model))
    throw InputError(
        "the exact leaf values need an identification problem (the state fixed until an action "
        "ends the episode), but " +
        *why + "; use --leaf lookahead for this one");
  return read_identification_tables(model, limits);
}

ExactBoundsGuide::ExactBoundsGuide(const pomdp::TabularModel& model, long offline_expansions)
    : ExactBoundsGuide(read_tables(model), offline_expansions) {}

ExactBoundsGuide::ExactBoundsGuide(std::shared_ptr<const IdentificationTables> tables,
                                   long offline_expansions)
    : tables_(std::move(tables)) {
  if (offline_expansions > 0) {
    offline_.emplace(tables_, planner_solver_options());
    offline_->refine(offline_->root(), RefineLimits{0.0, 0.0, offline_expansions});
  }
}

void ExactBoundsGuide::reset(const std::vector<double>& belief) {
  if (offline_)
    solver_.emplace(*offline_);
  else
    solver_.emplace(tables_, planner_solver_options());
  evaluated_.clear();
  const std::vector<double> start = solver_->belief(solver_->root());
  double distance = 0.0;
  for (std::size_t s = 0; s < start.size(); ++s)
    distance += std::abs(start[s] - (s < belief.size() ? belief[s] : 0.0));
  root_ = 0.5 * distance <= kStartBeliefTolerance ? solver_->root() : kNone;
}

void ExactBoundsGuide::follow(int action, int observation) {
  root_ = child(root_, action, observation);
}

std::vector<double> ExactBoundsGuide::root_belief() const {
  if (!active()) throw std::logic_error("ExactBoundsGuide::root_belief() while off");
  return solver_->belief(root_);
}

void ExactBoundsGuide::refine_root(const RefineLimits& limits) {
  if (active()) solver_->refine(root_, limits);
}

ExactBoundsGuide::NodeId ExactBoundsGuide::child(NodeId node, int action, int observation) {
  if (node == kNone || !solver_->is_sensing_action(action) || observation < 0 ||
      observation >= solver_->num_observations() || !solver_->available(node, action))
    return kNone;
  return solver_->child(node, action, observation);
}

double ExactBoundsGuide::leaf_value(NodeId node) {
  if (node == kNone) return 0.0;
  const auto index = static_cast<std::size_t>(node);
  if (evaluated_.size() <= index) evaluated_.resize(solver_->num_nodes(), 0);
  if (!evaluated_[index]) {
    evaluated_[index] = 1;
    solver_->refine(node, kLeafLookahead);
  }
  return solver_->value(node).lower;
}

double ExactBoundsGuide::clamp(NodeId node, double estimate) const {
  if (node == kNone) return estimate;
  const Bounds v = solver_->value(node);
  return std::clamp(estimate, v.lower, v.upper);
}

Bounds ExactBoundsGuide::action_bounds(int action) const {
  if (!active()) throw std::logic_error("ExactBoundsGuide::action_bounds() while off");
  return solver_->action_value(root_, action);
}

}  // namespace echoplan::solvers
