// The one-step expansion of a belief that every backup needs: all its children at once.
//
// b_ao(s') = P(o | s', a) * sum_s P(s' | s, a) b(s) / P(o | b, a), for every o, sharing the
// prediction step. (Tracking one belief during execution is pomdp::ExactBelief's job.)
#pragma once

#include <vector>

#include "solvers/offline/flat_pomdp.h"

namespace echoplan::solvers::offline {

// The children of belief b under action a: one entry per observation. When P(o | b, a) = 0 the
// entry holds the predicted belief (a harmless stand-in: it carries zero weight).
struct BeliefExpansion {
  std::vector<double> observation_probability;  // [o], sums to 1
  std::vector<BeliefVector> next_belief;        // [o][s']
};

// The predicted belief sum_s P(s' | s, a) b(s), before any observation.
BeliefVector predict(const FlatPomdp& pomdp, const BeliefVector& belief, int action);

BeliefExpansion expand(const FlatPomdp& pomdp, const BeliefVector& belief, int action);

// Expected immediate reward sum_s b(s) R(s, a) (terminal states contribute 0).
double expected_reward(const FlatPomdp& pomdp, const BeliefVector& belief, int action);

}  // namespace echoplan::solvers::offline
