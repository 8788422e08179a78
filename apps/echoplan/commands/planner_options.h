// The flags shared by the commands that plan (trials, run): which solver, its search settings and
// its budget per step, each defaulting to the problem file's planner section
// (solvers/planner_overrides.h says how they combine; loop/planner.h builds the solver).
#pragma once

#include <CLI/CLI.hpp>

#include "solvers/planner_overrides.h"

namespace echoplan::cli {

// A CLI11 check: the flag must be a number above 0, with a message that says so.
CLI::Validator positive();

// Adds --solver, --policy, --episodes, --step-ms and the search options to `cmd`.
void add_planner_options(CLI::App& cmd, solvers::PlannerOverrides& flags);

}  // namespace echoplan::cli
