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

#include <optional>
#include <vector>

#include "solvers/search_tree.h"
#include "solvers/sensing_policy.h"

namespace echoplan::solvers {

class AbtSolver final : public TreeSearchSolver {
 public:
  // Throws InputError when the leaf mode is `policy` and the model is not a tabular identification
  // problem.
  AbtSolver(pomdp::ModelPtr model, SearchOptions options);

  void reset(const pomdp::Belief& belief, Rng& rng) override;
  void update(int action, const pomdp::Observation& observation, const pomdp::Belief& belief_after,
              Rng& rng) override;

 protected:
  void run_episode(Rng& rng) override;
  void root_particle_added(BeliefNode& root, const pomdp::State& state, Rng& rng) override;

 private:
  // Steps `state` once with every action (into one_step_each_) and adds the rewards to the node's
  // per-action sums.
  void evaluate_particle(BeliefNode& node, const pomdp::State& state, Rng& rng);
  // Q(b, a) from the action's children and the immediate reward: its expectation under the node's
  // exact `belief` when there is one (leaf mode `policy`), else the mean over the node's particles.
  double action_value(const BeliefNode& node, int action, const std::vector<double>* belief) const;

  // One step of the episode's path: the belief node, the action taken there and the observation
  // branch followed (-1 when the step was terminal).
  struct PathStep {
    BeliefNode* node;
    int action;
    std::ptrdiff_t child;
  };
  std::vector<PathStep> path_;  // reused between episodes
  // Leaf mode `policy` only: the default policy, and the root's exact belief over the model's
  // tabular states (from the belief at reset, then by Bayes' rule from step to step).
  std::optional<SensingPolicy> policy_;
  std::vector<double> root_belief_;
  // The exact belief at each node of the episode's path (path_beliefs_[i] at depth i; the last is
  // the node the episode ended at).
  std::vector<std::vector<double>> path_beliefs_;
  std::vector<double> belief_scratch_;
  std::vector<pomdp::StepResult> one_step_each_;  // reused between particles
};

}  // namespace echoplan::solvers
