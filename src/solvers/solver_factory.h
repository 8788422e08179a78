// The one place that builds a solver by the name users type - "abt", "pomcp", "offline" or a
// baseline strategy (baseline_strategies.h: all_actions, best_single, ...) - with
// the search options and per-step budget a problem file and a user's overrides ask for
// (planner_overrides.h). What `echoplan trials`, `echoplan run`, campaigns and the ROS planner node
// plan with (through loop::make_planner, which only wraps it).
//
// It knows every solver, so it is compiled into the offline solver's library (echoplan::
// offline_solver), the top of the solvers module: link that to use it. make_solver.h's
// make_solver(name, model, options) is its online part, for callers that already hold search
// options (tests, benchmarks).
#pragma once

#include <memory>
#include <string>

#include "pomdp/problem.h"
#include "solvers/planner_overrides.h"
#include "solvers/search_tree.h"
#include "solvers/solver.h"

namespace echoplan::solvers {

// A solver, ready to reset(), and what it was built with.
struct BuiltSolver {
  std::string name;       // "abt", "pomcp", "offline" or a strategy
  SearchOptions options;  // the online solvers' search options (the offline solver ignores them)
  Budget budget;          // search per step
  std::unique_ptr<Solver> solver;
};

// The solver `overrides` name (else the problem file's), with options and budget from
// search_options() and budget(). "offline" loads overrides.policy, or solves the problem with the
// point-based solver now (a warning says how long it may take). Throws InputError for an unknown
// name, options out of range, or a --policy given to an online solver. `problem_path` names the
// problem in messages.
BuiltSolver make_solver(const PlannerOverrides& overrides, const pomdp::Problem& problem,
                        const std::string& problem_path);

}  // namespace echoplan::solvers
