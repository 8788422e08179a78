// Per-action use limits (pomdp::Model::max_uses) and the counting of uses along a history.
//
// A limit is a fact about the episode's history, not the state: "press" may be performed once per
// episode because the dataset holds one recording of it per session. A solver therefore counts the
// uses along each path it considers (from the start of the episode: the real steps it was told
// about, then the path in its tree or rollout) and offers only the actions still available there.
// A model without limits gives an empty UseLimits, and every check is then a single test of
// emptiness, so such problems plan exactly as before (same choices, same random draws).
#pragma once

#include <vector>

#include "pomdp/model.h"

namespace echoplan::solvers {

// How often each action was taken so far in an episode (indexed by action).
using UseCounts = std::vector<int>;

class UseLimits {
 public:
  UseLimits() = default;
  // Reads model.max_uses(a) for every action; empty when no action has a limit.
  explicit UseLimits(const pomdp::Model& model);
  // From a list per action (0: no limit); empty when none is positive.
  explicit UseLimits(std::vector<int> max_uses);

  // True when some action has a limit.
  bool any() const { return !max_uses_.empty(); }
  // The limit of `action`; 0: none.
  int max_uses(int action) const { return any() ? max_uses_[action] : 0; }
  // True when `action` may be taken once more after `uses` (an empty `uses` counts as none).
  bool allows(const UseCounts& uses, int action) const {
    if (!any() || max_uses_[action] == 0) return true;
    return (uses.empty() ? 0 : uses[action]) < max_uses_[action];
  }
  // Counts one more use of `action` (sizing `uses` to the actions on first use). Nothing when no
  // action has a limit, so solvers may call it unconditionally.
  void count(UseCounts& uses, int action) const {
    if (!any()) return;
    uses.resize(max_uses_.size(), 0);
    ++uses[action];
  }
  // The limits per action (empty when none).
  const std::vector<int>& per_action() const { return max_uses_; }

 private:
  std::vector<int> max_uses_;  // per action, 0: no limit; empty when none is positive
};

}  // namespace echoplan::solvers
