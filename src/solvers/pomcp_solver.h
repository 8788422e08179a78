// POMCP (Silver & Veness 2010): UCT over action-observation histories with a particle root belief.
//
// Each simulation starts from a root particle, chooses actions by UCB, steps the model, files each
// state as a particle of the history node it reaches, and ends at a terminal step, a new leaf
// (valued by the leaf estimate, leaf_value.h - classic POMCP uses a random rollout, which fails on
// the report's problem) or the depth limit. Each action node keeps the running mean of the
// discounted returns sampled through it (Monte-Carlo backup). The tree is kept across real steps
// like ABT's.
#pragma once

#include "solvers/search_tree.h"

namespace echoplan::solvers {

class PomcpSolver final : public TreeSearchSolver {
 public:
  PomcpSolver(pomdp::ModelPtr model, SearchOptions options);

 protected:
  void run_episode(Rng& rng) override;

 private:
  // The discounted return of one simulation from `node` (at `depth`) in `state`.
  double simulate(BeliefNode& node, pomdp::State state, int depth, Rng& rng);

  UseCounts path_uses_;  // the episode's uses (real steps, then its path) where it stands now
};

}  // namespace echoplan::solvers
