// A belief as exact probabilities over the states of a TabularModel, updated by Bayes' rule:
//   b'(s') ∝ O(a, s', o) · Σ_s T(s, a, s') b(s).
//
// Solvers receive full model states: each tabular state s is represented by the model's
// tabular_state(s), whose continuous part (if any) is advanced with the model's step on each
// update (exact for deterministic kinematics such as the object problem's slide).
// When the observation has probability 0 under the belief (or its index is out of range), the
// update keeps the predicted belief Σ_s T(s, a, ·) b(s), i.e. ignores the observation, and
// returns false.
#pragma once

#include <vector>

#include "pomdp/belief.h"

namespace echoplan::pomdp {

class ExactBelief final : public Belief {
 public:
  // The model's initial belief. Throws std::invalid_argument when model->tabular() is null.
  explicit ExactBelief(ModelPtr model);

  State sample(Rng& rng) const override;
  bool update(int action, const Observation& observation, Rng& rng) override;
  // Marginal over the values of discrete variable `variable`, from each tabular state's
  // representative; states without such a value (the object problem's 'done') are left out.
  std::vector<double> discrete_marginal(int variable) const override;
  std::unique_ptr<Belief> clone() const override;

  // P(tabular state s) for every s; sums to 1.
  const std::vector<double>& probabilities() const { return probabilities_; }
  const std::vector<double>* exact_probabilities() const override { return &probabilities_; }

 private:
  ModelPtr model_;
  const TabularModel* tabular_;
  std::vector<double> probabilities_;
  std::vector<State> representatives_;  // one model state per tabular state
  std::vector<double> predicted_;       // scratch for update()
};

}  // namespace echoplan::pomdp
