// Builds an online solver by the name users type ("abt", "pomcp", or a baseline strategy of
// baseline_strategies.h, which ignores the options) from search options already made.
// The online part of the one factory, solver_factory.h's make_solver(overrides, problem, path),
// which also builds the offline solver and derives options and budget; use that one unless you
// hold SearchOptions already (tests, benchmarks).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "pomdp/model.h"
#include "solvers/search_tree.h"
#include "solvers/solver.h"

namespace echoplan::solvers {

// The search solvers make_solver() accepts; it also accepts strategy_names()
// (baseline_strategies.h).
std::vector<std::string> solver_names();

// Throws InputError for an unknown name or invalid options.
std::unique_ptr<Solver> make_solver(const std::string& name, pomdp::ModelPtr model,
                                    const SearchOptions& options);

}  // namespace echoplan::solvers
