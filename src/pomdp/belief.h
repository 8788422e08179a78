// Beliefs: what the agent thinks the hidden state is, and how that changes with what it does and
// hears.
//
// Two implementations live in this module: ParticleBelief (sequential importance resampling with
// reinvigoration, as the report's OPPT setup used) and ExactBelief (Bayes filter over a
// TabularModel). Solvers only sample from a belief; the execution loop updates it.
#pragma once

#include <memory>
#include <vector>

#include "common/rng.h"
#include "pomdp/model.h"

namespace echoplan::pomdp {

class Belief {
 public:
  virtual ~Belief() = default;

  // A state drawn from the belief.
  virtual State sample(Rng& rng) const = 0;

  // Conditions the belief on having taken `action` and received `observation`. Never leaves the
  // belief empty: when nothing explains the observation, implementations recover (reinvigoration
  // for particles, a documented fallback for exact beliefs) and report it through the return value.
  // Returns true when the update was regular, false when it had to recover.
  virtual bool update(int action, const Observation& observation, Rng& rng) = 0;

  // The marginal probability of each value of discrete state variable `variable` (e.g. the object),
  // summing to 1.
  virtual std::vector<double> discrete_marginal(int variable) const = 0;

  virtual std::unique_ptr<Belief> clone() const = 0;

  // P(tabular state s) for every state of the model's tables when this belief is kept exactly over
  // them (ExactBelief); nullptr for a belief that only samples (particles). Lets a solver that
  // needs exact probabilities ask for them without knowing the implementation.
  virtual const std::vector<double>* exact_probabilities() const { return nullptr; }
};

using BeliefPtr = std::unique_ptr<Belief>;

}  // namespace echoplan::pomdp
