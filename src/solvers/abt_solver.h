// ABT: the Adaptive Belief Tree solver (Kurniawati & Yadav 2013), the solver the seed ran through
// OPPT.
//
// Each episode starts from a particle of the root, walks down the belief tree choosing actions by
// UCB, steps the model, files the resulting state as a particle of the belief node its observation
// leads to, and stops at a terminal step, at a new leaf (valued by the leaf estimate, leaf_value.h)
// or at the depth limit. The backup then recomputes, along the episode's path only,
//   Q(b, a) = rbar(b, a) + gamma * sum_o (n_o / n) V(b_ao),   V(b) = max_a Q(b, a),
// from the statistics of every episode that passed through (b, a) - the belief-tree backup of ABT,
// rather than POMCP's running average of sampled returns. rbar(b, a) is the immediate reward of a
// averaged over *all* particles filed in b (each is stepped once with every action when it
// arrives), not only over the episodes that happened to try a: a sorting action's value is -100 or
// +10 per particle, and estimating it from a handful of visits made ABT sort on too little
// evidence. Particles stay in their nodes, so after a real step the kept child is a ready-made
// belief.
//
// Not done here: ABT's revision of stored episodes when the model changes (echoplan's models never
// change while planning).
#pragma once

#include <vector>

#include "solvers/search_tree.h"

namespace echoplan::solvers {

class AbtSolver final : public TreeSearchSolver {
 public:
  AbtSolver(pomdp::ModelPtr model, SearchOptions options);

 protected:
  void run_episode(Rng& rng) override;
  void root_particle_added(BeliefNode& root, const pomdp::State& state, Rng& rng) override;

 private:
  // Steps `state` once with every action (into one_step_each_) and adds the rewards to the node's
  // per-action sums.
  void evaluate_particle(BeliefNode& node, const pomdp::State& state, Rng& rng);
  // Q(b, a) from the node's particle rewards and the action's children.
  double action_value(const BeliefNode& node, int action) const;

  // One step of the episode's path: the belief node, the action taken there and the observation
  // branch followed (-1 when the step was terminal).
  struct PathStep {
    BeliefNode* node;
    int action;
    std::ptrdiff_t child;
  };
  std::vector<PathStep> path_;                    // reused between episodes
  std::vector<pomdp::StepResult> one_step_each_;  // reused between particles
};

}  // namespace echoplan::solvers
