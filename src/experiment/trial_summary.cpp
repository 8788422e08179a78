#include "experiment/trial_summary.h"

#include <cmath>

namespace echoplan::experiment {

TrialSummary summarize(const std::vector<TrialRecord>& trials, int num_actions) {
  TrialSummary s;
  s.trials = static_cast<int>(trials.size());
  s.mean_action_counts.assign(num_actions, 0.0);
  if (trials.empty()) return s;
  const double n = static_cast<double>(trials.size());
  for (const TrialRecord& t : trials) {
    s.accuracy += (t.believed_state == t.true_state) / n;
    s.mean_discounted_reward += t.discounted_reward / n;
    s.mean_steps += t.steps / n;
    for (int a = 0; a < num_actions; ++a) s.mean_action_counts[a] += t.action_counts[a] / n;
    s.collisions += t.collision;
    s.capped += t.capped;
  }
  if (trials.size() > 1) {
    double squares = 0.0;
    for (const TrialRecord& t : trials) {
      const double d = t.discounted_reward - s.mean_discounted_reward;
      squares += d * d;
    }
    s.sd_discounted_reward = std::sqrt(squares / (n - 1.0));
    // 1.96 standard errors: the normal approximation, fine for the >= 30 trials studies use.
    s.ci95 = 1.96 * s.sd_discounted_reward / std::sqrt(n);
  }
  return s;
}

}  // namespace echoplan::experiment
