// Saving and loading the offline solver's alpha vectors as JSON, so a later run (trials) can act on
// a policy without solving again.
//
// Format (one object):
//   {"format": "echoplan-alpha-vectors", "version": 1, "num_states": S, "num_actions": A,
//    "discount": g, "lower": L, "upper": U,
//    "vectors": [{"action": a, "values": [v_0, ..., v_{S-1}]}, ...]}
// lower/upper are the bounds at the model's b0 when the file was written (informational).
#pragma once

#include <string>

#include "solvers/alpha_vector_set.h"
#include "solvers/offline/point_based_solver.h"

namespace echoplan::solvers::offline {

// Writes the solver's lower-bound vectors and root bounds to `path`. Throws InputError when the
// file cannot be written.
void save_policy(const PointBasedSolver& solver, const std::string& path);

// Reads vectors written by save_policy and checks they fit `pomdp` (state and action counts, and
// the discount they were solved at).
// Throws InputError naming the file, the line (for JSON syntax errors) and the problem.
AlphaVectorSet load_policy(const std::string& path, const FlatPomdp& pomdp);
// The same for the text of such a file; `path` names it in errors.
AlphaVectorSet parse_policy(const std::string& text, const std::string& path,
                            const FlatPomdp& pomdp);

}  // namespace echoplan::solvers::offline
