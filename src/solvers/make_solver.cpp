#include "solvers/make_solver.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "common/error.h"
#include "solvers/abt_solver.h"
#include "solvers/baseline_strategies.h"
#include "solvers/pomcp_solver.h"

namespace echoplan::solvers {

std::vector<std::string> solver_names() { return {"abt", "pomcp"}; }

std::unique_ptr<Solver> make_solver(const std::string& name, pomdp::ModelPtr model,
                                    const SearchOptions& options) {
  if (name == "abt") return std::make_unique<AbtSolver>(std::move(model), options);
  if (name == "pomcp") return std::make_unique<PomcpSolver>(std::move(model), options);
  if (is_strategy(name)) return make_strategy(name, std::move(model));
  throw InputError(fmt::format("solver '{}' is not one of {}, {}", name,
                               fmt::join(solver_names(), ", "), fmt::join(strategy_names(), ", ")));
}

}  // namespace echoplan::solvers
