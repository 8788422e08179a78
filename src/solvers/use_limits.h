// Per-action use limits (pomdp::Model::max_uses) and prerequisites (pomdp::Model::prerequisites),
// and the counting of uses along a history.
//
// Both are facts about the episode's history, not the state: "press" may be performed once per
// episode because the dataset holds one recording of it per session, and "shake" only after
// "grasp" because a robot shakes what it holds. A solver therefore counts the uses along each path
// it considers (from the start of the episode: the real steps it was told about, then the path in
// its tree or rollout) and offers only the actions still available there. A model with neither
// gives an empty UseLimits, and every check is then a single test of emptiness, so such problems
// plan exactly as before (same choices, same random draws).
#pragma once

#include <vector>

#include "pomdp/model.h"

namespace echoplan::solvers {

// How often each action was taken so far in an episode (indexed by action).
using UseCounts = std::vector<int>;

class UseLimits {
 public:
  UseLimits() = default;
  // Reads model.max_uses(a) and model.prerequisites(a) for every action; empty when no action has
  // either.
  explicit UseLimits(const pomdp::Model& model);
  // From a list per action (0: no limit) and, optionally, each action's prerequisites (one list
  // per action, or none at all); empty when no limit is positive and no action has a
  // prerequisite. Throws std::invalid_argument on a negative limit, a prerequisite list per
  // action of the wrong length, or a prerequisite that is not an action.
  explicit UseLimits(std::vector<int> max_uses, std::vector<std::vector<int>> prerequisites = {});

  // True when some action has a limit or a prerequisite.
  bool any() const { return !max_uses_.empty(); }
  // The limit of `action`; 0: none.
  int max_uses(int action) const { return any() ? max_uses_[action] : 0; }
  // The actions `action` waits for (each taken at least once); empty: none.
  const std::vector<int>& prerequisites(int action) const {
    static const std::vector<int> kNone;
    return prerequisites_.empty() ? kNone : prerequisites_[action];
  }
  // True when `action` may be taken once more after `uses` (an empty `uses` counts as none): its
  // limit is not spent and each of its prerequisites has been taken.
  bool allows(const UseCounts& uses, int action) const {
    return allows_after([&](int a) { return uses.empty() ? 0 : uses[a]; }, action);
  }
  // The same with the uses told by `used(a)` (how often action a was taken), for callers that
  // keep them in their own form.
  template <class Used>
  bool allows_after(Used used, int action) const {
    if (!any()) return true;
    if (max_uses_[action] > 0 && used(action) >= max_uses_[action]) return false;
    for (int r : prerequisites(action))
      if (used(r) == 0) return false;
    return true;
  }
  // Counts one more use of `action` (sizing `uses` to the actions on first use). Nothing when no
  // action has a limit or a prerequisite, so solvers may call it unconditionally.
  void count(UseCounts& uses, int action) const {
    if (!any()) return;
    uses.resize(max_uses_.size(), 0);
    ++uses[action];
  }

 private:
  // Per action, 0: no limit; empty when no action has a limit or a prerequisite.
  std::vector<int> max_uses_;
  // Per action its prerequisites; empty when no action has one.
  std::vector<std::vector<int>> prerequisites_;
};

}  // namespace echoplan::solvers
