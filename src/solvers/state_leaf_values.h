// The leaf values computed from the states (particles) that reach a leaf: `lookahead`, `heuristic`
// and `rollout` (leaf_value.h says what each estimates and why). Every tree-search solver may use
// them; they hold nothing between calls, so the model they step is the one in each visit.
#pragma once

#include "solvers/leaf_value.h"

namespace echoplan::solvers {

// The best single next step: for each action, the mean of r(s, a) + gamma * h(s') over the
// particles (0 after a terminal step), maximised over actions.
class LookaheadLeafValue final : public LeafValue {
 public:
  void add(LeafEstimate& estimate, const LeafVisit& visit, Rng& rng) override;
};

// The mean of the model's heuristic_value over the particles.
class HeuristicLeafValue final : public LeafValue {
 public:
  void add(LeafEstimate& estimate, const LeafVisit& visit, Rng& rng) override;
};

// The mean discounted return of uniformly random play from each particle, plus gamma^k * h at the
// depth limit (classic POMCP).
class RolloutLeafValue final : public LeafValue {
 public:
  void add(LeafEstimate& estimate, const LeafVisit& visit, Rng& rng) override;
};

}  // namespace echoplan::solvers
