// The belief a problem file asks for: a particle filter of the configured size or the exact
// Bayes filter (which needs a problem with tables; InputError otherwise, naming the file).
#pragma once

#include "pomdp/belief.h"
#include "pomdp/problem.h"

namespace echoplan::pomdp {

// Draws the initial particles from `rng` when the problem selects the particle filter.
BeliefPtr make_belief(const Problem& problem, Rng& rng);

}  // namespace echoplan::pomdp
