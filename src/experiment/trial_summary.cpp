#include "experiment/trial_summary.h"

#include "common/statistics.h"

namespace echoplan::experiment {

namespace {

bool right(const TrialRecord& t, const std::vector<int>& right_action) {
  if (right_action.empty()) return t.believed_state == t.true_state;
  return t.action_counts.at(right_action.at(t.true_state)) > 0;
}

}  // namespace

double share_right(const std::vector<TrialRecord>& trials, const std::vector<int>& right_action) {
  if (trials.empty()) return 0.0;
  double share = 0.0;
  for (const TrialRecord& t : trials) share += right(t, right_action) / double(trials.size());
  return share;
}

TrialSummary summarize(const std::vector<TrialRecord>& trials, int num_actions,
                       const std::vector<int>& right_action,
                       const std::vector<double>& action_costs) {
  TrialSummary s;
  s.trials = static_cast<int>(trials.size());
  s.mean_action_counts.assign(num_actions, 0.0);
  if (trials.empty()) return s;
  const double n = static_cast<double>(trials.size());
  s.accuracy = share_right(trials, right_action);
  for (const TrialRecord& t : trials) {
    s.mean_discounted_reward += t.discounted_reward / n;
    s.mean_steps += t.steps / n;
    for (int a = 0; a < num_actions; ++a) s.mean_action_counts[a] += t.action_counts[a] / n;
    for (std::size_t a = 0; a < action_costs.size(); ++a)
      s.mean_cost += t.action_counts.at(a) * action_costs[a] / n;
    s.collisions += t.collision;
    s.capped += t.capped;
  }
  std::vector<double> rewards;
  for (const TrialRecord& t : trials) rewards.push_back(t.discounted_reward);
  const MeanInterval m = mean_ci95(rewards);
  s.sd_discounted_reward = m.sd;
  s.ci95 = m.half_width;
  return s;
}

}  // namespace echoplan::experiment
