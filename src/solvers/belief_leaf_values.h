// The leaf values that follow the exact belief over a tabular identification problem's states
// (ABT only): `policy` rolls the default sensing policy out from each leaf's belief, `exact` and
// `exact-offline` take the exact solver's lower bound there (leaf_value.h says why, and
// exact_bounds_guide.h how).
#pragma once

#include <vector>

#include "solvers/exact_bounds_guide.h"
#include "solvers/leaf_value.h"
#include "solvers/sensing_policy.h"

namespace echoplan::solvers {

// Leaf mode `policy`. Follows the root's exact belief (from the belief at reset, then by Bayes'
// rule from step to step) and each episode's beliefs below it.
class PolicyLeafValue : public LeafValue {
 public:
  // `model` must be a tabular identification problem; throws InputError otherwise.
  explicit PolicyLeafValue(pomdp::ModelPtr model);

  void add(LeafEstimate& estimate, const LeafVisit& visit, Rng& rng) override;
  void reset(const pomdp::Belief& belief) override;
  void follow(int action, const pomdp::Observation& observation,
              const pomdp::Belief& belief_after) override;
  void start_episode() override { path_beliefs_.assign(1, root_belief_); }
  void descend(std::size_t depth, int action, int observation) override;
  const std::vector<double>* exact_belief(std::size_t depth) const override {
    return &path_beliefs_[depth];
  }
  const SensingPolicy* belief_model() const override { return &policy_; }

 protected:
  // On identification tables already read (shared with the exact solver).
  PolicyLeafValue(pomdp::ModelPtr model, std::shared_ptr<const IdentificationTables> tables);

  std::vector<double> root_belief_;

 private:
  pomdp::ModelPtr model_;  // its tables are followed
  SensingPolicy policy_;
  // The exact belief at each step of the episode being walked (path_beliefs_[i] at depth i).
  std::vector<std::vector<double>> path_beliefs_;
  std::vector<double> belief_scratch_;
};

// Leaf modes `exact` and `exact-offline` (the latter with an offline solve made at construction).
// While the exact solver holds the root's belief (ExactBoundsGuide::active()) its lower bound
// values the leaves, its bounds clamp every node and decide at the root, and it is refined for
// `exact_share` of every step's budget; otherwise (a start belief far from the problem's) the
// leaves are valued as by `policy`. The sensing policy and the exact solver share one
// IdentificationTables.
class ExactLeafValue final : public PolicyLeafValue {
 public:
  // `offline_expansions` > 0: the offline solve's expansions (`exact-offline`); 0: none (`exact`).
  ExactLeafValue(pomdp::ModelPtr model, double exact_share, long offline_expansions);
  ExactLeafValue(pomdp::ModelPtr model, const std::shared_ptr<const IdentificationTables>& tables,
                 double exact_share, long offline_expansions);

  void add(LeafEstimate& estimate, const LeafVisit& visit, Rng& rng) override;
  void reset(const pomdp::Belief& belief) override;
  void follow(int action, const pomdp::Observation& observation,
              const pomdp::Belief& belief_after) override;
  void start_episode() override;
  void descend(std::size_t depth, int action, int observation) override;
  Budget episode_budget(const Budget& budget) override;
  double clamp(std::size_t depth, double value) const override;
  int root_decision(int actions) const override;

 private:
  bool guided() const { return guide_.active(); }

  double exact_share_;
  ExactBoundsGuide guide_;
  // The solver node of each step of the episode being walked (path_nodes_[i] at depth i).
  std::vector<ExactBoundsGuide::NodeId> path_nodes_;
};

}  // namespace echoplan::solvers
