// A planner's settings as Python keyword arguments: the same names and meanings as the flags of
// `echoplan trials` (docs/planning.md), each left out keeping the problem file's setting.
#pragma once

#include <pybind11/pybind11.h>

#include "solvers/planner_overrides.h"

namespace echoplan::python {

// The overrides `settings` asks for: solver, policy, episodes, step_ms, exploration, depth, leaf,
// expand_after, exact_share, offline_expansions, root_particles, branch_threshold. TypeError for
// any other name, naming the known ones.
solvers::PlannerOverrides planner_overrides(const pybind11::kwargs& settings);

// The docstring paragraph that lists them.
const char* planner_settings_doc();

}  // namespace echoplan::python
