// summarize(): the statistics of a set of trials against values worked out by hand.
#include "experiment/trial_summary.h"

#include <gtest/gtest.h>

#include <cmath>

namespace echoplan::experiment {
namespace {

TrialRecord trial(int true_state, int believed_state, int steps, std::vector<int> counts,
                  double reward) {
  TrialRecord t;
  t.true_state = true_state;
  t.believed_state = believed_state;
  t.steps = steps;
  t.action_counts = std::move(counts);
  t.discounted_reward = reward;
  return t;
}

TEST(TrialSummary, ThreeTrialsByHand) {
  std::vector<TrialRecord> trials = {trial(0, 0, 2, {1, 1, 0}, 1.0), trial(1, 0, 4, {2, 1, 1}, 2.0),
                                     trial(2, 2, 3, {0, 2, 1}, 6.0)};
  trials[1].collision = true;
  trials[2].capped = true;
  const TrialSummary s = summarize(trials, 3);
  EXPECT_EQ(s.trials, 3);
  EXPECT_DOUBLE_EQ(s.accuracy, 2.0 / 3.0);  // trials 0 and 2 believed the truth
  EXPECT_DOUBLE_EQ(s.mean_discounted_reward, 3.0);
  // Deviations -2, -1, 3: squares sum to 14, over n - 1 = 2 gives variance 7.
  EXPECT_NEAR(s.sd_discounted_reward, std::sqrt(7.0), 1e-12);
  // t(0.975, 2) = 4.302652730 (tables) times sd / sqrt(3).
  EXPECT_NEAR(s.ci95, 4.302652730 * std::sqrt(7.0) / std::sqrt(3.0), 1e-8);
  EXPECT_DOUBLE_EQ(s.mean_steps, 3.0);
  ASSERT_EQ(s.mean_action_counts.size(), 3u);
  EXPECT_DOUBLE_EQ(s.mean_action_counts[0], 1.0);
  EXPECT_DOUBLE_EQ(s.mean_action_counts[1], 4.0 / 3.0);
  EXPECT_DOUBLE_EQ(s.mean_action_counts[2], 2.0 / 3.0);
  EXPECT_EQ(s.collisions, 1);
  EXPECT_EQ(s.capped, 1);
}

TEST(TrialSummary, MeanCostIsEachTrialsUsesTimesTheirCosts) {
  // Costs: action 0 at 0.5, action 1 at 4, action 2 (a sort) at 0. Trial costs: 1·0.5 + 1·4 = 4.5,
  // 2·0.5 + 1·4 = 5, 0 + 2·4 = 8; mean 17.5 / 3.
  const std::vector<TrialRecord> trials = {trial(0, 0, 2, {1, 1, 0}, 1.0),
                                           trial(1, 0, 4, {2, 1, 1}, 2.0),
                                           trial(2, 2, 3, {0, 2, 1}, 6.0)};
  EXPECT_DOUBLE_EQ(summarize(trials, 3, {}, {0.5, 4.0, 0.0}).mean_cost, 17.5 / 3.0);
  EXPECT_EQ(summarize(trials, 3).mean_cost, 0.0);  // without costs: none reported
}

TEST(TrialSummary, OneTrialHasNoInterval) {
  const TrialSummary s = summarize({trial(1, 1, 5, {3, 2}, -4.5)}, 2);
  EXPECT_EQ(s.trials, 1);
  EXPECT_EQ(s.accuracy, 1.0);
  EXPECT_EQ(s.mean_discounted_reward, -4.5);
  EXPECT_EQ(s.sd_discounted_reward, 0.0);
  EXPECT_EQ(s.ci95, 0.0);
  EXPECT_EQ(s.mean_action_counts, (std::vector<double>{3.0, 2.0}));
}

TEST(TrialSummary, NoTrialsGiveZerosWithOneCountPerAction) {
  const TrialSummary s = summarize({}, 4);
  EXPECT_EQ(s.trials, 0);
  EXPECT_EQ(s.accuracy, 0.0);
  EXPECT_EQ(s.mean_discounted_reward, 0.0);
  EXPECT_EQ(s.mean_action_counts, std::vector<double>(4, 0.0));
  EXPECT_EQ(s.collisions, 0);
}

}  // namespace
}  // namespace echoplan::experiment
