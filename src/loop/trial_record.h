// What a trial leaves for the logs: one record per real step and one per trial. These are what a
// campaign's journal keeps, what steps.csv and trials.csv hold, and what `echoplan certify` reads
// back.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "pomdp/model.h"

namespace echoplan::loop {

// One real step of a trial. `belief` is the belief the action was chosen from: the marginal of
// discrete state variable 0 (for the report's problem, the object), one probability per value.
struct StepRecord {
  int trial = 0;
  int step = 0;  // 0-based
  int action = 0;
  pomdp::Observation observation;
  std::vector<double> belief;
  double reward = 0.0;
  std::int64_t episodes = 0;  // search episodes run for this decision
  // The observation service's calibrated probability of the heard class; absent when the world
  // has no classifier (the model as the world samples its table).
  std::optional<double> heard_probability;
  // The event-to-background ratio measured from the heard recording (audio/levels.h), in dB;
  // absent without one.
  std::optional<double> heard_ebr_db;
};

// One finished trial. `believed_state` is the most likely value of discrete variable 0 under the
// final belief (the one the last action was chosen from).
struct TrialRecord {
  int trial = 0;
  int true_state = 0;
  int believed_state = 0;
  int steps = 0;
  std::vector<int> action_counts;  // per action
  double discounted_reward = 0.0;  // sum_t gamma^t r_t
  bool collision = false;
  bool capped = false;  // stopped by max_steps rather than by a terminal step
  // The surface the world's robot acted on (robot::ActionReport::surface); empty when it names
  // none.
  std::string surface;
};

}  // namespace echoplan::loop
