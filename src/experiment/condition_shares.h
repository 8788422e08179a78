// One arm's trials under one condition (a band of noise level, a table): how many, the share of
// the sorts that were right beside the mean belief at the sort (sort_confidence.h), the recordings
// heard, the behaviours performed and their cost per trial.
#pragma once

#include <vector>

#include "experiment/sort_confidence.h"
#include "experiment/trial_journal.h"

namespace echoplan::experiment {

struct ConditionShares {
  int trials = 0;
  int sorts = 0;                 // trials that sorted (not capped)
  double share_right = 0.0;      // of the sorts; 0 when none
  double mean_belief = 0.0;      // at the sort; 0 when none
  double mean_heard = 0.0;       // recordings heard per trial; 0 when no trial
  double mean_behaviours = 0.0;  // sensing actions per trial (the steps but the sort)
  double mean_cost = 0.0;        // their cost per trial: uses x `action_costs`
  // Counts `trial`; `action_costs` per action (campaign_report.h's action_costs(), empty: none).
  // Call finish() once every trial is added.
  void add(const TrialResult& trial, const RightShares& right_share,
           const std::vector<double>& action_costs);
  // Turns the sums into the means above.
  void finish();
};

}  // namespace echoplan::experiment
