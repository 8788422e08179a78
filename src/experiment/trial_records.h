// The loop's records as the experiment layer keeps them: a campaign's journal, trials.csv and
// steps.csv, the reports and certificates read these (the clips and the robot's reports stay with
// the loop's own log, loop/loop_log.h).
#pragma once

#include <vector>

#include "loop/trial_record.h"
#include "loop/trial_runner.h"

namespace echoplan::experiment {

using loop::StepRecord;
using loop::TrialRecord;

// A finished trial's records.
struct TrialResult {
  TrialRecord record;
  std::vector<StepRecord> steps;
};

inline TrialResult records_of(const loop::Trial& trial) {
  TrialResult result{trial.record, {}};
  result.steps.reserve(trial.steps.size());
  for (const loop::Step& s : trial.steps) result.steps.push_back(s.record);
  return result;
}

}  // namespace echoplan::experiment
