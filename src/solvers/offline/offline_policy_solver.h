// The offline solver's result driven through the online Solver interface, so that the trials runner
// can run it as solver `offline` next to ABT and POMCP.
//
// All planning happened beforehand (PointBasedSolver, or a policy file): improve() does nothing,
// and best_action() is the first action of the best lower-bound alpha vector at the current belief,
// so acting this way earns at least the lower bound. The belief is tracked exactly
// (pomdp::ExactBelief over the model's tables), whatever belief the execution loop keeps for
// itself.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "pomdp/exact_belief.h"
#include "solvers/alpha_vector_set.h"
#include "solvers/offline/flat_pomdp.h"
#include "solvers/offline/point_based_solver.h"
#include "solvers/solver.h"

namespace echoplan::solvers::offline {

class OfflinePolicySolver final : public Solver {
 public:
  // `model` must have tables (tabular()), `pomdp` must be made from them, and `vectors` must be
  // non-empty with one value per tabular state; throws std::invalid_argument otherwise.
  OfflinePolicySolver(pomdp::ModelPtr model, std::shared_ptr<const FlatPomdp> pomdp,
                      AlphaVectorSet vectors);

  // Starts from `belief` when it is exact over the same model's tables (exact_probabilities()),
  // else from the model's b0.
  void reset(const pomdp::Belief& belief, Rng& rng) override;
  // Nothing to do: the policy was computed offline.
  void improve(const Budget& budget, Rng& rng) override;
  int best_action() const override;
  // Lower bounds on Q*(b, a) by one-step lookahead on the alpha vectors.
  std::vector<double> root_action_values() const override;
  // Bayes update of the exact belief with (action, observation); `belief_after` is not needed.
  void update(int action, const pomdp::Observation& observation, const pomdp::Belief& belief_after,
              Rng& rng) override;
  SolverStats stats() const override { return {}; }

  // P(tabular state) now.
  const std::vector<double>& belief() const { return *belief_->exact_probabilities(); }
  // The lower bound on the value of acting with this policy from the current belief.
  double value() const { return vectors_.value(belief()); }

 private:
  pomdp::ModelPtr model_;
  std::shared_ptr<const FlatPomdp> pomdp_;
  AlphaVectorSet vectors_;
  pomdp::BeliefPtr belief_;  // always exact: exact_probabilities() is never null
};

// For the trials runner: solves `model` offline (PointBasedSolver with `options`) and wraps the
// result, or, when `policy_path` is not empty, loads that policy file (written by `echoplan solve
// --out`) instead. Throws InputError when the model has no tables or the file does not fit.
std::unique_ptr<Solver> make_offline_solver(const pomdp::ModelPtr& model,
                                            const SolverOptions& options,
                                            const std::string& policy_path = "",
                                            const std::string& source = "");

}  // namespace echoplan::solvers::offline
