// The offline solver's alpha-vector policy behind the online Solver interface, so `echoplan trials
// --solver offline` runs it like ABT and POMCP.
//
// The policy keeps its own exact belief (Bayes filter over the problem's tables), starting from the
// problem's initial belief b0 at reset(); the Belief objects the trial runner passes in are not read
// (a particle belief cannot give the exact distribution the alpha vectors need). improve() does no
// work: all planning happened offline, so the search statistics stay at zero.
#pragma once

#include "solvers/offline/alpha_vector_policy.h"
#include "solvers/solver.h"

namespace echoplan::solvers::offline {

class OfflinePolicySolver final : public Solver {
 public:
  OfflinePolicySolver(AlphaVectorPolicy policy, int num_actions)
      : policy_(std::move(policy)), num_actions_(num_actions) {}

  void reset(const pomdp::Belief& /*belief*/, Rng& /*rng*/) override { policy_.reset(); }
  void improve(const Budget& /*budget*/, Rng& /*rng*/) override {}
  int best_action() const override { return policy_.best_action(); }
  // Only the chosen action's value is known (the policy's lower bound); the others are NaN.
  std::vector<double> root_action_values() const override;
  void update(int action, const pomdp::Observation& observation,
              const pomdp::Belief& /*belief_after*/, Rng& /*rng*/) override {
    policy_.update(action, observation.index);
  }
  SolverStats stats() const override { return {}; }

 private:
  AlphaVectorPolicy policy_;
  int num_actions_;
};

}  // namespace echoplan::solvers::offline
