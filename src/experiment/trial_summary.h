// The statistics of a set of trials: accuracy, mean discounted reward and its 95% confidence
// interval.
#pragma once

#include <optional>
#include <vector>

#include "common/statistics.h"
#include "experiment/trial_records.h"

namespace echoplan::experiment {

struct TrialSummary {
  int trials = 0;
  // Fraction of trials whose final belief's mode is the truth; with `right_action` (summarize), the
  // fraction sorted right.
  double accuracy = 0.0;
  // `echoplan trials` on an object problem: the fraction whose sorting action was right for the
  // true object (its decision region), beside the identity's `accuracy`.
  std::optional<double> sorted_right;
  double mean_discounted_reward = 0.0;
  double sd_discounted_reward = 0.0;  // sample standard deviation (n - 1); 0 for one trial
  double ci95 = 0.0;                  // half-width of the 95% CI of the mean (Student's t)
  double mean_steps = 0.0;
  std::vector<double> mean_action_counts;  // per action
  // What the trials' actions cost on average (summarize()'s `action_costs`); 0 without costs.
  double mean_cost = 0.0;
  int collisions = 0;
  int capped = 0;  // trials stopped by --max-steps
  // The model as the world with an exact belief (`echoplan trials`): the trials' reward in
  // expectation given what they heard (expected_reward.h), its mean and 95% CI; n = 0 elsewhere.
  MeanInterval expected_reward;
};

// The share of `trials` right: with `right_action` (below), sorted right; without, whose final
// belief's mode is the truth. 0 without trials.
double share_right(const std::vector<TrialRecord>& trials,
                   const std::vector<int>& right_action = {});

// `right_action[s]`, when given, is the action that sorts true state s right (a dataset world sorts
// objects by group, so knowing the group is enough): a trial is right when it took that action.
// `action_costs[a]`, when given (one per action), is what one use of action a costs: mean_cost is
// the mean over trials of Σ_a uses × cost.
TrialSummary summarize(const std::vector<TrialRecord>& trials, int num_actions,
                       const std::vector<int>& right_action = {},
                       const std::vector<double>& action_costs = {});

}  // namespace echoplan::experiment
