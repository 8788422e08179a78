// One arm's trials under one condition (a band of noise level, a table): how many, the share of
// the sorts that were right beside the mean belief at the sort (sort_confidence.h), and the
// recordings heard per trial.
#pragma once

#include "experiment/sort_confidence.h"
#include "experiment/trial_journal.h"

namespace echoplan::experiment {

struct ConditionShares {
  int trials = 0;
  int sorts = 0;             // trials that sorted (not capped)
  double share_right = 0.0;  // of the sorts; 0 when none
  double mean_belief = 0.0;  // at the sort; 0 when none
  double mean_heard = 0.0;   // recordings heard per trial; 0 when no trial
  // Counts `trial`; call finish() once every trial is added.
  void add(const TrialResult& trial, const RightShares& right_share);
  // Turns the sums into the means above.
  void finish();
};

}  // namespace echoplan::experiment
