// The value a search tree assigns to a belief node it has not expanded yet.
//
// Why this matters: on the seed's problem a uniformly random rollout makes sensing look worthless
// next to the -100 of a wrong sort (random play sorts wrongly half the time), so a planner valuing
// leaves by random rollouts commits after about one observation (about -28 against V* = 2.95).
// Four estimators are offered:
//
//   policy               the value of a default policy that senses with the most informative action
//                        until confident and then commits (sensing_policy.h), rolled out from the
//                        node's exact belief over the states of a tabular identification problem;
//                        the best of its stopping thresholds counts. A lower bound in expectation,
//                        which the search improves on. ABT only; needs model tables.
//   exact                the exact solver's lower bound at the node's belief
//   (exact_bounds_guide.h):
//                        the value of a plan the IdentificationSolver knows there, after one
//                        lookahead over its children's bounds. The same solver is refined at the
//                        root for `exact_share` of every step's budget, and its [lower, upper]
//                        bounds on V* clamp every node's value; at the root, an action its bounds
//                        prove optimal is taken outright. Everything comes from the problem file
//                        within the step's budget. ABT only; identification problems only.
//   exact-offline        `exact`, but every trial starts from a solve of `offline_expansions`
//                        expansions made once, before the first step (reported apart: it is not
//                        computed within the per-step budget).
//   lookahead  the belief-level value of the best single next step: for each action, the
//                        mean over the node's particles of r(s, a) + gamma * h(s') (h = the model's
//                        heuristic_value; 0 after a terminal step), maximised over actions. For an
//                        object-identification problem that is "commit now to the best sorting
//                        action for this belief, or sense once more and then rely on h".
//   heuristic            the mean of the model's heuristic_value over the node's particles.
//   rollout              the mean discounted return of uniformly random play from each particle
//                        (classic POMCP), plus gamma^k * h at the depth limit. For comparison.
//
// A node stays a leaf until `expand_after` particles have reached it, so the belief-level estimate
// averages over more than one state before the search branches below it.
#pragma once

#include <string>
#include <vector>

#include "common/rng.h"
#include "pomdp/model.h"
#include "solvers/sensing_policy.h"

namespace echoplan::solvers {

enum class LeafMode { policy, exact, exact_offline, lookahead, heuristic, rollout };

// Parses "policy" | "exact" | "exact-offline" | "lookahead" | "heuristic" | "rollout"; throws
// InputError naming the flag otherwise.
LeafMode parse_leaf_mode(const std::string& text);
const char* leaf_mode_name(LeafMode mode);

// The leaf value a solver uses unless told otherwise: `policy` for ABT on a tabular identification
// problem, `lookahead` everywhere else. (`exact` measured better there, docs/BENCHMARKS.md
// "Certified share of V*", but as the default it fails the ROS loop test whose microphone carries
// no evidence: docs/planning.md.)
LeafMode default_leaf_mode(const std::string& solver, const pomdp::Model& model);

struct LeafOptions {
  LeafMode mode = LeafMode::lookahead;
  int expand_after = 4;  // >= 1: visits a node spends as a leaf before it is expanded
  // Modes exact and exact-offline: the share of each step's budget spent refining the exact
  // solver at the root before the episodes, in [0, 1] (of the milliseconds; with an episode budget
  // of N, N * share solver expansions and N * (1 - share) episodes, at least one).
  double exact_share = 1.0;
  // Mode exact-offline: expansions of the solve made before the first step; >= 1.
  long offline_expansions = 200000;
};

// Running estimate of an unexpanded node's value, updated as particles arrive.
class LeafEstimate {
 public:
  // Adds `state` (a particle that reached the node) to the estimate. `steps_left` bounds a rollout.
  // `one_step_each` (optional): the result of stepping `state` once with each action, when the
  // caller already has it; the lookahead estimate then reuses it instead of stepping again.
  void add(const LeafOptions& options, const pomdp::Model& model, const pomdp::State& state,
           int steps_left, Rng& rng, const std::vector<pomdp::StepResult>* one_step_each = nullptr);
  // Mode `policy`: adds `rollouts` rollouts of `policy` from the node's exact `belief` (over the
  // tabular states), at most `steps_left` steps each.
  void add_rollouts(const SensingPolicy& policy, const std::vector<double>& belief, int steps_left,
                    int rollouts, Rng& rng);
  // The current estimate; 0 before any particle was added.
  double value() const;
  int count() const { return count_; }
  // The accumulated sums; the difference across one add() is that particle's contribution.
  const std::vector<double>& sums() const { return sums_; }
  // Takes back one particle's `contribution` (as measured across its add()), for a solver that
  // revises its episodes (AbtSolver::revise).
  void remove(const std::vector<double>& contribution);
  // Sets the estimate to `value` (a leaf valued as a whole rather than particle by particle: the
  // exact modes).
  void set(double value);
  // Frees the accumulators (the node was expanded and no longer needs them).
  void release();

 private:
  std::vector<double> sums_;  // lookahead: one per action; policy: one per threshold; else one
  int count_ = 0;
};

}  // namespace echoplan::solvers
