// The solver a problem file and a user's overrides ask for, with its search options and budget:
// what `echoplan trials`, `echoplan run` and the ROS planner node plan with.
#pragma once

#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "pomdp/problem.h"
#include "solvers/planner_overrides.h"
#include "solvers/search_tree.h"
#include "solvers/solver.h"

namespace echoplan::experiment {

// The solver, ready to reset().
struct Planner {
  std::string name;  // "abt", "pomcp" or "offline"
  solvers::SearchOptions options;
  solvers::Budget budget;
  std::unique_ptr<solvers::Solver> solver;

  // "abt, 2000 episodes/step"
  std::string describe() const;
  // The settings for summary files: solver, budget and search options.
  nlohmann::json to_json() const;
};

// Throws InputError for an unknown solver or options out of range. `problem_path` names the problem
// in messages (and the offline solver's progress).
Planner make_planner(const solvers::PlannerOverrides& overrides, const pomdp::Problem& problem,
                     const std::string& problem_path);

}  // namespace echoplan::experiment
