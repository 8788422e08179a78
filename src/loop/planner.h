// The solver a problem file and a user's overrides ask for, with its search options and budget:
// what every loop (`echoplan trials`, `run`, the ROS planner node, a campaign's arms) plans with.
#pragma once

#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "pomdp/problem.h"
#include "solvers/planner_overrides.h"
#include "solvers/search_tree.h"
#include "solvers/solver.h"

namespace echoplan::loop {

// The solver, ready to reset().
struct Planner {
  std::string name;  // "abt", "pomcp", "offline" or a strategy (solvers/baseline_strategies.h)
  solvers::SearchOptions options;
  solvers::Budget budget;
  std::unique_ptr<solvers::Solver> solver;

  // "abt, 2000 episodes/step"; "random (fixed strategy, no search)"
  std::string describe() const;
  // The settings for summary files: solver, budget and search options.
  nlohmann::json to_json() const;
};

// Throws InputError for an unknown solver or options out of range. `problem_path` names the problem
// in messages (and the offline solver's progress).
// The checks make_planner() makes, without building the solver (the offline one solves when built):
// a known solver name, --policy only with it, search options and budget in range.
void check_planner(const solvers::PlannerOverrides& overrides, const pomdp::Problem& problem);

Planner make_planner(const solvers::PlannerOverrides& overrides, const pomdp::Problem& problem,
                     const std::string& problem_path);

}  // namespace echoplan::loop
