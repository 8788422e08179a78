#include "loop/planner.h"

#include <fmt/core.h>
#include <fmt/ranges.h>

#include <algorithm>

#include "common/error.h"
#include "solvers/baseline_strategies.h"
#include "solvers/make_solver.h"
#include "solvers/solver_factory.h"

namespace echoplan::loop {

void check_planner(const solvers::PlannerOverrides& f, const pomdp::Problem& problem) {
  const std::string name = f.solver.empty() ? problem.planner.solver : f.solver;
  const auto online = solvers::solver_names();
  if (name != "offline" && std::find(online.begin(), online.end(), name) == online.end() &&
      !solvers::is_strategy(name))
    throw InputError(fmt::format("solver '{}' is not one of {}, offline, {}", name,
                                 fmt::join(online, ", "),
                                 fmt::join(solvers::strategy_names(), ", ")));
  if (!f.policy.empty() && name != "offline")
    throw InputError("--policy is for --solver offline; the " + name +
                     " solver plans online and would ignore it");
  solvers::search_options(f, problem);
  if (solvers::budget(f, problem).amount < 1)
    throw InputError("the search budget (--episodes / --step-ms) must be >= 1");
}

Planner make_planner(const solvers::PlannerOverrides& f, const pomdp::Problem& problem,
                     const std::string& problem_path) {
  check_planner(f, problem);
  solvers::BuiltSolver built = solvers::make_solver(f, problem, problem_path);
  Planner p;
  p.name = std::move(built.name);
  p.options = built.options;
  p.budget = built.budget;
  p.solver = std::move(built.solver);
  return p;
}

std::string Planner::describe() const {
  if (solvers::is_strategy(name)) return name + " (fixed strategy, no search)";
  return budget.kind == solvers::Budget::Kind::episodes
             ? fmt::format("{}, {} episodes/step", name, budget.amount)
             : fmt::format("{}, {} ms/step", name, budget.amount);
}

nlohmann::json Planner::to_json() const {
  return {
      {"solver", name},
      {"budget",
       {{budget.kind == solvers::Budget::Kind::episodes ? "episodes" : "step_ms", budget.amount}}},
      {"search",
       {{"exploration", options.exploration},
        {"max_depth", options.max_depth},
        {"leaf", solvers::leaf_mode_name(options.leaf.mode)},
        {"unheard", solvers::unheard_outcomes_name(options.unheard)},
        {"expand_after", options.leaf.expand_after},
        {"root_particles", options.root_particles},
        {"branch_threshold", options.branching.continuous_threshold}}}};
}

}  // namespace echoplan::loop
