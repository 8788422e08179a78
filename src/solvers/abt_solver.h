// ABT: the Adaptive Belief Tree solver (Kurniawati & Yadav 2013), the solver the seed ran through OPPT.
//
// Each episode starts from a particle of the root, walks down the belief tree choosing actions by UCB,
// steps the model, files the resulting state as a particle of the belief node its observation leads
// to, and stops at a terminal step, at a new leaf (valued by the leaf estimate, leaf_value.h) or at the
// depth limit. The backup then recomputes, along the episode's path only,
//   Q(b, a) = mean immediate reward + gamma * sum_o (n_o / n) V(b_ao),   V(b) = max_a Q(b, a),
// from the statistics of every episode that passed through (b, a) - the belief-tree backup of ABT,
// rather than POMCP's running average of sampled returns. Particles stay in their nodes, so after a
// real step the kept child is a ready-made belief for the next decision.
//
// Not done here: ABT's revision of stored episodes when the model changes (echoplan's models never
// change while planning).
#pragma once

#include "solvers/search_tree.h"

namespace echoplan::solvers {

class AbtSolver final : public TreeSearchSolver {
 public:
  AbtSolver(pomdp::ModelPtr model, SearchOptions options);

 protected:
  void run_episode(Rng& rng) override;

 private:
  // One step of the episode's path: the belief node, the action taken there and the observation
  // branch followed (-1 when the step was terminal).
  struct PathStep {
    BeliefNode* node;
    ActionNode* action;
    std::ptrdiff_t child;
  };
  std::vector<PathStep> path_;  // reused between episodes to avoid reallocation
};

}  // namespace echoplan::solvers
