#include "experiment/condition_shares.h"

#include <algorithm>

namespace echoplan::experiment {

void ConditionShares::add(const TrialResult& trial, const RightShares& right_share) {
  ++trials;
  mean_heard += static_cast<double>(
      std::count_if(trial.steps.begin(), trial.steps.end(),
                    [](const loop::StepRecord& s) { return s.heard_ebr_db.has_value(); }));
  if (const std::optional<SortConfidence> sort = sort_confidence(trial, right_share)) {
    ++sorts;
    mean_belief += sort->belief;
    share_right += sort->right;
  }
}

void ConditionShares::finish() {
  if (trials) mean_heard /= trials;
  if (sorts) mean_belief /= sorts, share_right /= sorts;
}

}  // namespace echoplan::experiment
