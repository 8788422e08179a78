// Options shared by the commands that plan (trials, run): which solver, its search settings and its
// budget per step, each defaulting to the problem file's planner section.
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "pomdp/problem.h"
#include "solvers/leaf_value.h"
#include "solvers/search_tree.h"
#include "solvers/solver.h"

namespace echoplan::cli {

struct PlannerFlags {
  std::string solver;  // empty: the problem file's
  std::string policy;  // --solver offline: alpha vectors from `echoplan solve --out`
  std::int64_t episodes = 0;
  std::int64_t step_ms = 0;
  // Search options; a negative value means "the problem file's (or the built-in) default".
  double exploration = -1;
  int depth = -1;
  std::string leaf;  // empty: solvers::default_leaf_mode()
  int expand_after = solvers::LeafOptions{}.expand_after;
  int root_particles = -1;
  double branch_threshold = 0.0;
};

// A CLI11 check: the flag must be a number above 0, with a message that says so.
CLI::Validator positive();

// Adds --solver, --policy, --episodes, --step-ms and the search options to `cmd`.
void add_planner_options(CLI::App& cmd, PlannerFlags& flags);

// The solver the flags and the problem ask for, ready to reset().
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
Planner make_planner(const PlannerFlags& flags, const pomdp::Problem& problem,
                     const std::string& problem_path);

}  // namespace echoplan::cli
