// The measures the baselines decide by, against hand computations on the two-object problem
// (tiny_identification_problems.h).
#include "solvers/strategy_measures.h"

#include <gtest/gtest.h>

#include "tiny_identification_problems.h"

namespace echoplan::solvers {
namespace {

constexpr int kTap = 0, kPress = 1, kShake = 2, kToA = 3, kToB = 4;

TEST(HeldOutAccuracy, IsThePriorWeightedChanceOfTheObjectsOwnSymbol) {
  const pomdp::ObjectProblemData d = testing::two_objects();
  EXPECT_NEAR(held_out_accuracy(d, kTap), 0.60, 1e-12);
  EXPECT_NEAR(held_out_accuracy(d, kPress), 0.85, 1e-12);
  EXPECT_NEAR(held_out_accuracy(d, kShake), 0.70, 1e-12);
  pomdp::ObjectProblemData skewed = d;
  skewed.prior = {0.8, 0.2};  // press: 0.8·0.9 + 0.2·0.8 = 0.88
  EXPECT_NEAR(held_out_accuracy(skewed, kPress), 0.88, 1e-12);
}

TEST(HeldOutAccuracy, SymbolsNotNamedLikeObjectsAreReadByBayesRule) {
  pomdp::ObjectProblemData d = testing::two_objects();
  // Tap with its symbols swapped: named like the objects, it would be right 0.5·0.2 + 0.5·0.1 =
  // 0.15 of the time.
  d.observation_table[kTap] = {{0.2, 0.8}, {0.9, 0.1}};
  EXPECT_NEAR(held_out_accuracy(d, kTap), 0.15, 1e-12);
  // Symbols x, y name no object: Σ_o max_k prior_k P(o | k) = max(0.1, 0.45) + max(0.4, 0.05).
  d.observation_symbols = {"x", "y"};
  EXPECT_NEAR(held_out_accuracy(d, kTap), 0.85, 1e-12);
}

TEST(SingleActionValue, IsTheCostPlusTheSortItsAccuracyEarns) {
  // Right bin 10, wrong bin -100 for both objects: value = r_a + 0.99 (-100 + 110 accuracy).
  pomdp::ObjectProblemData d = testing::two_objects();
  EXPECT_NEAR(single_action_value(d, kTap), -1 + 0.99 * (-100 + 110 * 0.60), 1e-12);  // -34.66
  EXPECT_NEAR(single_action_value(d, kPress), -1 + 0.99 * -6.5, 1e-12);               // -7.435
  EXPECT_NEAR(single_action_value(d, kShake), -1 + 0.99 * -23, 1e-12);                // -23.77
  d.sensing[kPress].reward = -20.0;
  EXPECT_NEAR(single_action_value(d, kPress), -20 + 0.99 * -6.5, 1e-12);  // -26.435
}

TEST(OneStepLookahead, CommitValueIsTheBestSortingActionsExpectedReward) {
  const auto model = testing::model_of(testing::two_objects());
  const OneStepLookahead look(*model->object_identification());
  EXPECT_DOUBLE_EQ(look.commit_value({0.5, 0.5}), 0.5 * 10 - 0.5 * 100);
  EXPECT_DOUBLE_EQ(look.commit_value({1.0, 0.0}), 10.0);
  EXPECT_DOUBLE_EQ(look.expected_reward({0.3, 0.7}, kToB), -30.0 + 7.0);
  EXPECT_DOUBLE_EQ(look.expected_reward({0.3, 0.7}, kToA), 3.0 - 70.0);
}

TEST(OneStepLookahead, SenseThenCommitAveragesTheBestCommitAfterEachSymbol) {
  const auto model = testing::model_of(testing::two_objects());
  const OneStepLookahead look(*model->object_identification());
  // Press at uniform: symbol a has joint probabilities (a 0.45, b 0.10), best commit to_a:
  // 4.5 - 10 = -5.5; symbol b (a 0.05, b 0.40), best to_b: -5 + 4 = -1. -1 + 0.99·(-6.5).
  EXPECT_NEAR(look.sense_then_commit_value({0.5, 0.5}, kPress), -1 + 0.99 * -6.5, 1e-12);
  // Tap: each symbol (0.3, 0.2) or (0.2, 0.3): best commit 3 - 20 = -17. -1 + 0.99·(-34).
  EXPECT_NEAR(look.sense_then_commit_value({0.5, 0.5}, kTap), -1 + 0.99 * -34, 1e-12);
  // Known object: sensing only delays the +10.
  EXPECT_NEAR(look.sense_then_commit_value({1.0, 0.0}, kShake), -1 + 0.99 * 10, 1e-12);
}

TEST(OneStepLookahead, ACollisionCostsItsRewardAndEndsTheEpisode) {
  pomdp::ObjectProblemData d = testing::two_objects();
  d.sensing[kPress].collision_probability = 0.5;
  const auto model = testing::model_of(d);
  const OneStepLookahead look(*model->object_identification());
  // Object a known: R = 0.5·(-1) + 0.5·(-100); the +10 comes only when no collision.
  EXPECT_NEAR(look.sense_then_commit_value({1.0, 0.0}, kPress), -50.5 + 0.99 * 0.5 * 10, 1e-12);
  // What press tells when it does not collide is unchanged (the next test's 0.275396).
  EXPECT_NEAR(look.expected_entropy_reduction({0.5, 0.5}, kPress), 0.275396, 1e-6);
}

TEST(OneStepLookahead, EntropyReductionIsWhatOneSymbolTellsOnAverage) {
  const auto model = testing::model_of(testing::two_objects());
  const OneStepLookahead look(*model->object_identification());
  // H(uniform) = ln 2 = 0.693147 nats.
  // shake: posterior (0.7, 0.3) either way, H = 0.610864: gain 0.082283.
  // press: symbol a (p 0.55) gives (0.818182, 0.181818), H = 0.474139; symbol b (p 0.45) gives
  //   (0.111111, 0.888889), H = 0.348832: gain 0.693147 - 0.417751 = 0.275396.
  // tap: posterior (0.6, 0.4), H = 0.673012: gain 0.020136.
  EXPECT_NEAR(look.expected_entropy_reduction({0.5, 0.5}, kShake), 0.082283, 1e-6);
  EXPECT_NEAR(look.expected_entropy_reduction({0.5, 0.5}, kPress), 0.275396, 1e-6);
  EXPECT_NEAR(look.expected_entropy_reduction({0.5, 0.5}, kTap), 0.020136, 1e-6);
  EXPECT_NEAR(look.expected_entropy_reduction({1.0, 0.0}, kPress), 0.0, 1e-12);
}

}  // namespace
}  // namespace echoplan::solvers
