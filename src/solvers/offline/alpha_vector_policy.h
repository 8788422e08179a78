// The offline solver's result used as a policy during execution: keep an exact belief (Bayes filter
// over the tables) and act on the best lower-bound alpha vector at it.
//
// This is what the trials runner drives as solver `offline`: reset(belief), best_action(),
// update(action, observation). Acting greedily on the vectors earns at least the lower bound.
#pragma once

#include <memory>
#include <vector>

#include "solvers/offline/alpha_vector_set.h"
#include "solvers/offline/dense_pomdp.h"

namespace echoplan::solvers::offline {

class AlphaVectorPolicy {
 public:
  // `vectors` must hold at least one vector of length pomdp->num_states.
  AlphaVectorPolicy(std::shared_ptr<const DensePomdp> pomdp, AlphaVectorSet vectors);

  // Starts an episode at `belief` (length num_states, sums to 1); defaults to the model's b0.
  void reset(const BeliefVector& belief);
  void reset() { reset(pomdp_->initial_belief); }

  int best_action() const { return vectors_.best_action(belief_); }
  // The lower bound on the value of acting with this policy from the current belief.
  double value() const { return vectors_.value(belief_); }

  // Conditions the belief on `action` and `observation` (Bayes filter). Returns false when the model
  // gives the observation probability 0; the belief then keeps the prediction and stays valid.
  bool update(int action, int observation);

  const BeliefVector& belief() const { return belief_; }
  const AlphaVectorSet& vectors() const { return vectors_; }

 private:
  std::shared_ptr<const DensePomdp> pomdp_;
  AlphaVectorSet vectors_;
  BeliefVector belief_;
};

}  // namespace echoplan::solvers::offline
