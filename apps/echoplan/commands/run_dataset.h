// `echoplan run --data DIR --session NAME`: one recorded session of a feature set or a recordings
// tree replayed through the loop with a trained model (`train --out`), as a dataset campaign
// replays it, with the same step log and trial.json as any other run.
#pragma once

#include <cstdint>
#include <string>

#include "solvers/planner_overrides.h"

namespace echoplan::cli {

struct RunDatasetFlags {
  std::string data;     // the feature set or recordings tree
  std::string session;  // the session of `object` to replay
  std::string object;   // an object of the data
  std::string groups;   // optional: the object's class is its group (a problem of groups)
  std::string model;    // required
  std::string problem;  // required: the data's problem (`train --problem-out`)
  std::uint64_t seed = 1;
  int max_steps = 100;
  std::string out;
  solvers::PlannerOverrides planner;
};

// Replays the session and prints each step. InputError for an unknown object or session (listing
// the known ones), a missing --model or --problem, a problem or model that does not fit the data.
// The trial's random streams come from (seed, the session's place among the object's sessions):
// with a campaign's trials.csv seed and the arm's solver it logs the campaign trial's steps.
void run_dataset_session(const RunDatasetFlags& flags);

}  // namespace echoplan::cli
