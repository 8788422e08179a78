#include "loop/planner.h"

#include <fmt/core.h>
#include <fmt/ranges.h>
#include <spdlog/spdlog.h>

#include <algorithm>

#include "common/error.h"
#include "solvers/make_solver.h"
#include "solvers/offline/offline_policy_solver.h"

namespace echoplan::loop {

void check_planner(const solvers::PlannerOverrides& f, const pomdp::Problem& problem) {
  const std::string name = f.solver.empty() ? problem.planner.solver : f.solver;
  const auto online = solvers::solver_names();
  if (name != "offline" && std::find(online.begin(), online.end(), name) == online.end())
    throw InputError(fmt::format("solver '{}' is not one of {}", name, fmt::join(online, ", ")));
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
  Planner p;
  p.name = f.solver.empty() ? problem.planner.solver : f.solver;
  p.options = solvers::search_options(f, problem);
  p.budget = solvers::budget(f, problem);
  if (p.name == "offline") {
    // The policy file when given, else the point-based solver run now (to its default precision or
    // time limit).
    if (f.policy.empty())
      spdlog::warn(
          "no --policy given: solving {} offline now, for up to {} s (save a policy once with "
          "`echoplan solve --method point-based --out DIR` and pass --policy DIR/policy.json)",
          problem_path, solvers::offline::SolverOptions{}.time_limit_seconds);
    p.solver = solvers::offline::make_offline_solver(problem.model, {}, f.policy, problem_path);
  } else {
    p.solver = solvers::make_solver(p.name, problem.model, p.options);
  }
  return p;
}

std::string Planner::describe() const {
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
        {"expand_after", options.leaf.expand_after},
        {"root_particles", options.root_particles},
        {"branch_threshold", options.branching.continuous_threshold}}}};
}

}  // namespace echoplan::loop
