// The exact solver's bounds steering ABT on an identification problem (leaf modes `exact` and
// `exact-offline`, leaf_value.h).
//
// On an identification problem every belief ABT's tree reaches is the belief of one count vector
// of the IdentificationSolver (identification_solver.h): the root's node follows the real steps,
// and a tree node's is its parent's child(a, o). The guide keeps one solver per trial (like the
// tree, it starts afresh at reset() and follows the real steps) and offers ABT:
//   - refine_root(): the solver's anytime refinement at the current belief, run inside the step's
//     budget, before the episodes;
//   - leaf_value(): the solver's lower bound at a new leaf after one full-width lookahead (the
//   value
//     of a plan the solver knows: a policy, so ABT's search above it can only improve on it);
//   - clamp(): a node's estimate moved into the solver's [lower, upper] bounds on V*, which hold
//     whatever the episodes sampled (the true value lies inside, so the clamped estimate is never
//     further from it);
//   - action_bounds(): the bounds on Q* at the root, on which the decision is made.
// With `offline_expansions` > 0 (leaf `exact-offline`), the solver is refined at the start belief
// with that many expansions once, when the guide is built, and every trial starts from a copy of
// that solve; without, every trial starts from the problem file alone.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "pomdp/model.h"
#include "solvers/identification_solver.h"

namespace echoplan::solvers {

class ExactBoundsGuide {
 public:
  using NodeId = IdentificationSolver::NodeId;
  static constexpr NodeId kNone = IdentificationSolver::kEnded;

  // `model`'s identification tables with the use `limits` of the Model they belong to; throws
  // InputError naming the reason when it is not an identification problem.
  static std::shared_ptr<const IdentificationTables> read_tables(const pomdp::TabularModel& model,
                                                                 const UseLimits& limits = {});
  // Throws InputError naming the reason when `model` is not an identification problem.
  ExactBoundsGuide(const pomdp::TabularModel& model, long offline_expansions);
  // The same on tables from read_tables() (shared with the sensing policy of the same leaves).
  ExactBoundsGuide(std::shared_ptr<const IdentificationTables> tables, long offline_expansions);

  // Starts a trial at `belief` (over the model's states). The solver's root is the problem's start
  // belief; a `belief` further from it than a particle sample's noise (total variation > 0.1)
  // leaves the guide off until the next reset (active() false), since no node holds that belief.
  void reset(const std::vector<double>& belief);
  // Moves the root along a real step; off for the rest of the trial when the step is not a
  // sensing action whose observation a live state can emit.
  void follow(int action, int observation);
  bool active() const { return root_ != kNone; }
  NodeId root() const { return root_; }
  // The root's exact belief over the model's states.
  std::vector<double> root_belief() const;

  // Refines the bounds at the root within `limits` (expansions or seconds).
  void refine_root(const RefineLimits& limits);
  // The node after sensing `action` heard `observation` at `node`; kNone when `node` is kNone or
  // the step cannot happen (then it ended the episode, or `action` is terminal).
  NodeId child(NodeId node, int action, int observation);
  // The solver's lower bound at `node` after one lookahead over its children's bounds (the first
  // time a node is asked; later only read). 0 for kNone.
  double leaf_value(NodeId node);
  // `estimate` moved into [lower, upper] of V* at `node` (unchanged for kNone).
  double clamp(NodeId node, double estimate) const;
  // Bounds on Q*(root, action).
  Bounds action_bounds(int action) const;

  const IdentificationSolver& solver() const { return *solver_; }

 private:
  std::optional<IdentificationSolver> offline_;         // the offline solve every trial starts from
  std::optional<IdentificationSolver> solver_;          // this trial's
  std::shared_ptr<const IdentificationTables> tables_;  // every trial's solver is built on them
  NodeId root_ = kNone;
  std::vector<char> evaluated_;  // per solver node: leaf_value() already looked ahead once
};

}  // namespace echoplan::solvers
