#include "experiment/condition_shares.h"

#include <algorithm>

namespace echoplan::experiment {

void ConditionShares::add(const TrialResult& trial, const RightShares& right_share,
                          const std::vector<double>& action_costs) {
  ++trials;
  const loop::TrialRecord& record = trial.record;
  mean_behaviours += record.steps - (record.capped ? 0 : 1);
  for (std::size_t a = 0; a < action_costs.size() && a < record.action_counts.size(); ++a)
    mean_cost += record.action_counts[a] * action_costs[a];
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
  if (trials) mean_heard /= trials, mean_behaviours /= trials, mean_cost /= trials;
  if (sorts) mean_belief /= sorts, share_right /= sorts;
}

}  // namespace echoplan::experiment
