#include "solvers/solver_factory.h"

#include <spdlog/spdlog.h>

#include "common/error.h"
#include "solvers/make_solver.h"
#include "solvers/offline/offline_policy_solver.h"

namespace echoplan::solvers {

BuiltSolver make_solver(const PlannerOverrides& f, const pomdp::Problem& problem,
                        const std::string& problem_path) {
  BuiltSolver built;
  built.name = f.solver.empty() ? problem.planner.solver : f.solver;
  if (!f.policy.empty() && built.name != "offline")
    throw InputError("--policy is for --solver offline; the " + built.name +
                     " solver plans online and would ignore it");
  built.options = search_options(f, problem);
  built.budget = budget(f, problem);
  if (built.name != "offline") {
    built.solver = make_solver(built.name, problem.model, built.options);
    return built;
  }
  // The policy file when given, else the point-based solver run now (to its default precision or
  // time limit).
  if (f.policy.empty())
    spdlog::warn(
        "no --policy given: solving {} offline now, for up to {} s (save a policy once with "
        "`echoplan solve --method point-based --out DIR` and pass --policy DIR/policy.json)",
        problem_path, offline::SolverOptions{}.time_limit_seconds);
  built.solver = offline::make_offline_solver(problem.model, {}, f.policy, problem_path);
  return built;
}

}  // namespace echoplan::solvers
