// The Bayes filter over a DensePomdp, and the one-step expansion of a belief that every backup needs.
//
// b_ao(s') = P(o | s', a) * sum_s P(s' | s, a) b(s) / P(o | b, a). The solver expands a belief into all
// its (observation probability, next belief) pairs at once, sharing the prediction step.
#pragma once

#include <vector>

#include "solvers/offline/dense_pomdp.h"

namespace echoplan::solvers::offline {

// The children of belief b under action a: one entry per observation. When P(o | b, a) = 0 the entry
// holds the predicted belief (a harmless stand-in: it carries zero weight).
struct BeliefExpansion {
  std::vector<double> observation_probability;  // [o], sums to 1
  std::vector<BeliefVector> next_belief;          // [o][s']
};

// The predicted belief sum_s P(s' | s, a) b(s), before any observation.
BeliefVector predict(const DensePomdp& pomdp, const BeliefVector& belief, int action);

BeliefExpansion expand(const DensePomdp& pomdp, const BeliefVector& belief, int action);

// Conditions `belief` on taking `action` and hearing `observation`. Returns false, leaving the
// predicted belief (the observation ignored), when the model gives the observation probability 0:
// the belief never becomes empty.
bool bayes_update(const DensePomdp& pomdp, BeliefVector& belief, int action, int observation);

// Expected immediate reward sum_s b(s) R(s, a) (terminal states contribute 0).
double expected_reward(const DensePomdp& pomdp, const BeliefVector& belief, int action);

}  // namespace echoplan::solvers::offline
