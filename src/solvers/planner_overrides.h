// What a user may change of a problem file's planner section (command-line flags, ROS parameters, a
// campaign's planner block), and the search options and budget that result. The one place that says
// how a problem's planner defaults and a user's choices combine.
#pragma once

#include <cstdint>
#include <string>

#include "pomdp/problem.h"
#include "solvers/leaf_value.h"
#include "solvers/search_tree.h"
#include "solvers/solver.h"

namespace echoplan::solvers {

// Each field left at its default keeps the problem file's (or the built-in) setting.
struct PlannerOverrides {
  std::string solver;  // "abt", "pomcp" or "offline"; empty: the problem file's
  std::string policy;  // offline: alpha vectors from `echoplan solve --out`; empty: solve now
  std::int64_t episodes = 0;  // search episodes per step; 0: not set
  std::int64_t step_ms = 0;   // search wall time per step; 0: not set (episodes win when both set)
  // Search options; a negative value means "the problem file's (or the built-in) default".
  double exploration = -1;
  int depth = -1;
  std::string leaf;     // policy, exact, exact-offline, lookahead, heuristic or rollout; empty:
                        // default_leaf_mode()
  std::string unheard;  // share or commit (search_tree.h, UnheardOutcomes); empty: share
  int expand_after = LeafOptions{}.expand_after;
  double exact_share = LeafOptions{}.exact_share;              // leaf exact / exact-offline
  long offline_expansions = LeafOptions{}.offline_expansions;  // leaf exact-offline
  int root_particles = -1;  // negative: the problem's belief size
  double branch_threshold = 0.0;
};

// The search options `problem` and `overrides` ask for. Throws InputError for an unknown leaf mode
// or an option out of range.
SearchOptions search_options(const PlannerOverrides& overrides, const pomdp::Problem& problem);

// The search per step: the overrides' episodes, else their step_ms, else the problem file's budget.
Budget budget(const PlannerOverrides& overrides, const pomdp::Problem& problem);

}  // namespace echoplan::solvers
