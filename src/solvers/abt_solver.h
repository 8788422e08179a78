// ABT: the Adaptive Belief Tree solver (Kurniawati & Yadav 2013), the solver the original system
// ran through OPPT.
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
// As published (with SearchOptions::keep_episodes), the tree keeps every episode as its sequence
// of (state, action, observation, reward) steps, each step linked to the belief node it was filed
// in, so that a model change revises the tree instead of rebuilding it: revise() re-samples the
// observation of every step that drew it from a changed row, and when the new observation leads to
// another branch, the episode's old continuation is taken out of the tree (particles, visits, leaf
// estimates) and the episode continues from the new branch with the search policy; the values along
// both paths are backed up again. What differs from the paper and OPPT's implementation: the new
// observation is drawn by a maximal coupling with the old one (kept with probability min(1,
// P_new(o)/P_old(o)), otherwise drawn from the excess of P_new over P_old), which is exactly a draw
// from P_new but keeps as many continuations as possible; and only observation-table changes are
// supported (the only part of echoplan's models that can change while a robot runs,
// model_change.h).
#pragma once

#include <cstdint>
#include <vector>

#include "solvers/model_change.h"
#include "solvers/search_tree.h"

namespace echoplan::solvers {

// What one revise() did.
struct RevisionStats {
  std::int64_t episodes = 0;              // episodes kept by the tree
  std::int64_t affected_steps = 0;        // steps whose observation came from a changed row
  std::int64_t kept_observations = 0;     // of those, steps whose observation stayed in its branch
  std::int64_t resimulated_episodes = 0;  // episodes whose continuation was replaced
};

class AbtSolver final : public TreeSearchSolver {
 public:
  // Throws InputError when the leaf mode is `policy`, `exact` or `exact-offline` and the model is
  // not a tabular identification problem. With `exact-offline` the offline solve runs here.
  AbtSolver(pomdp::ModelPtr model, SearchOptions options);

  void reset(const pomdp::Belief& belief, Rng& rng) override;
  // With the exact leaves: refines the exact solver at the root for the budget's exact_share
  // first, then runs episodes for the rest (at least one).
  void improve(const Budget& budget, Rng& rng) override;
  // With the exact leaves: the action with the highest lower bound on Q* from the exact solver (the
  // one its bounds prove optimal when they separate one).
  int best_action() const override;
  void update(int action, const pomdp::Observation& observation, const pomdp::Belief& belief_after,
              Rng& rng) override;

  // Plans with change.model from now on and revises the stored episodes that used a changed
  // observation row, so that the tree is what episodes sampled from the new model would have
  // built (up to the search policy's choices, which stay as they were where nothing changed).
  // For a model with continuous observations, the affected step is re-stepped with the new model
  // instead of coupled. Throws InputError when the new model's actions, observations or discount
  // differ, std::logic_error before reset(), when options().keep_episodes is off or with the policy
  // leaf (its values depend on the table at every node).
  RevisionStats revise(const ModelChange& change, Rng& rng);

  // Episodes stored in the tree (those passing through the current root; 0 unless keep_episodes).
  std::int64_t stored_episodes() const { return static_cast<std::int64_t>(episodes_.size()); }

 protected:
  void run_episode(Rng& rng) override;
  void root_particle_added(BeliefNode& root, const pomdp::State& state, Rng& rng) override;
  void before_reroot(const BeliefNode* kept) override;

 private:
  // One (state, action, observation, reward) step of a stored episode.
  struct EpisodeStep {
    BeliefNode* node;  // the belief node the state is filed in
    pomdp::State state;
    int action = -1;  // -1: the episode ended here, valued by the node's leaf estimate
    pomdp::Observation observation;
    double reward = 0.0;
    bool terminal = false;
    std::ptrdiff_t child = -1;              // the observation branch followed; -1 if none
    std::vector<double> particle_rewards;   // the state's reward under every action, as filed
    std::vector<double> leaf_contribution;  // leaf steps: what the state added to the estimate
  };
  using Episode = std::vector<EpisodeStep>;

  // Steps `state` once with every action (into one_step_each_) and adds the rewards to the node's
  // sums; returns them (rewards_, valid until the next call).
  const std::vector<double>& evaluate_particle(BeliefNode& node, const pomdp::State& state,
                                               Rng& rng);
  // Q(b, a) from the action's children and the immediate reward: its expectation under the node's
  // exact `belief` when there is one (LeafValue::exact_belief()), else the mean over the node's
  // particles.
  // Q(node, action); `belief` (the exact belief at the node, when the leaf value tracks one)
  // weighs the children by P(o | b, a), cached in the nodes while the belief stays the same.
  double action_value(BeliefNode& node, int action, const std::vector<double>* belief) const;
  // The exact belief at step `i` of the episode being walked or backed up (leaf modes `policy`,
  // `exact`, `exact-offline`), else nullptr.
  const std::vector<double>* step_belief(std::size_t i) const {
    return leaf_value().exact_belief(i);
  }
  // Walks `episode` on from `node` at `depth` with `state` (filed there unless depth is 0). The
  // steps record the path (node, action, branch); with keep_episodes also everything revise()
  // needs to take the step back out. The leaf value follows the walk (LeafValue::descend()).
  void simulate_from(Episode& episode, BeliefNode* node, pomdp::State state, int depth, Rng& rng);
  // Takes step `i` (depth > 0) of `episode` out of the tree's statistics.
  void remove_step(const EpisodeStep& step);
  // Recomputes the values along episode steps [0, last], deepest first.
  void backup(const Episode& episode, std::size_t last);
  // Folds the current value of `action`'s child `child` into its future_sum.
  static void refresh_child(ActionNode& action, std::size_t child);
  void recompute_node_value(BeliefNode& node) const;
  // Draws the new observation of an affected step by a maximal coupling with the old one.
  pomdp::Observation couple_observation(const pomdp::Model& before, const EpisodeStep& step,
                                        const pomdp::State& next, Rng& rng) const;

  std::vector<Episode> episodes_;  // with keep_episodes
  Episode path_;                   // the current episode otherwise (reused)
  UseCounts path_uses_;  // the episode's uses (real steps, then its path) where it stands now
  // With an exact belief at the root, its Q values change only in backups (which recompute the
  // action they pass through): they are refreshed at the first episode of each improve() alone.
  bool root_values_stale_ = true;
  std::vector<pomdp::StepResult> one_step_each_;  // reused between particles
  std::vector<double> rewards_;                   // reused between particles
};

}  // namespace echoplan::solvers
