// The measures the baselines decide by, against hand computations on the two- and four-object
// problems (tiny_identification_problems.h).
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

TEST(OneStepLookahead, EntropyReductionCountsDistinctionsTheSortDoesNotNeed) {
  // Four objects at uniform, H = ln 4 = 1.386294. Split: either symbol (P 0.5) leaves
  // (0.5, 0, 0.25, 0.25), H = 1.039721: gain 0.346574 (a1 from a2, one bin). Bins: either symbol
  // leaves (0.4, 0.4, 0.1, 0.1), H = 1.193550: gain 0.192745 (= ln 2 - H(0.2)).
  const auto model = testing::model_of(testing::four_objects());
  const OneStepLookahead look(*model->object_identification());
  EXPECT_NEAR(look.expected_entropy_reduction({0.25, 0.25, 0.25, 0.25}, 0), 0.346574, 1e-6);
  EXPECT_NEAR(look.expected_entropy_reduction({0.25, 0.25, 0.25, 0.25}, 1), 0.192745, 1e-6);
}

// The four-object problem: split 0, bins 1; regions a1, a2 -> to_A (0), b1, b2 -> to_B (1).
constexpr int kSplit = 0, kBins = 1;

TEST(DecisionRegions, EachObjectsBestBinTheFirstOnTies) {
  EXPECT_EQ(decision_regions(testing::four_objects()), (std::vector<int>{0, 0, 1, 1}));
  // three_objects: x +10 in A against -10 in B; y, z +10 in B.
  EXPECT_EQ(decision_regions(testing::three_objects()), (std::vector<int>{0, 1, 1}));
  pomdp::ObjectProblemData d = testing::three_objects();
  d.sorting_reward = {{10, 5, -100}, {-10, 5, 10}};  // y as good in either bin: the first
  EXPECT_EQ(decision_regions(d), (std::vector<int>{0, 0, 1}));
}

TEST(EdgeCut, EdgeMassJoinsObjectsOfDifferentRegions) {
  const EdgeCut cut(testing::four_objects());
  // Uniform: 4 edges (a_i, b_j) of 1/16 each.
  EXPECT_NEAR(cut.edge_mass({0.25, 0.25, 0.25, 0.25}), 0.25, 1e-15);
  // (0.4, 0.3, 0.2, 0.1): 0.08 + 0.04 + 0.06 + 0.03 = 0.7 · 0.3.
  EXPECT_NEAR(cut.edge_mass({0.4, 0.3, 0.2, 0.1}), 0.21, 1e-15);
  EXPECT_NEAR(cut.edge_mass({0.5, 0.5, 0.0, 0.0}), 0.0, 1e-15);  // the bin is known
}

TEST(EdgeCut, ExpectedCutIsEcedsDiscountAtTheBelief) {
  const EdgeCut cut(testing::four_objects());
  // Consistencies λ(o|k) (each row over its largest entry): split a1 (1, 0), a2 (0, 1), b1, b2
  // (1, 1); bins a (1, 0.25), b (0.25, 1). Every symbol is some object's likeliest: m(o) = 1.
  // Uniform, split: x (P 0.5) leaves a1-b edges (λλ' 1) and cuts a2-b (λλ' 0): 2/16; y the same:
  // 0.5·0.125 + 0.5·0.125 = 0.125. Bins: either symbol (P 0.5) discounts all 4 edges by
  // 1 - 0.25 = 0.75: 0.75 · 0.25 = 0.1875. The bins action cuts more, though split tells more
  // about the identity (0.346574 nats against 0.192745: baseline_strategies_test).
  const std::vector<double> uniform{0.25, 0.25, 0.25, 0.25};
  EXPECT_NEAR(cut.expected_cut(uniform, kSplit), 0.125, 1e-12);
  EXPECT_NEAR(cut.expected_cut(uniform, kBins), 0.1875, 1e-12);
  // (0.4, 0.3, 0.2, 0.1), split: x (P 0.4 + 0.1 + 0.05 = 0.55) cuts a2-b, 0.06 + 0.03; y (P 0.45)
  // cuts a1-b, 0.08 + 0.04: 0.55·0.09 + 0.45·0.12 = 0.1035. Bins: 0.75 · 0.21 = 0.1575 whatever
  // is heard.
  EXPECT_NEAR(cut.expected_cut({0.4, 0.3, 0.2, 0.1}, kSplit), 0.1035, 1e-12);
  EXPECT_NEAR(cut.expected_cut({0.4, 0.3, 0.2, 0.1}, kBins), 0.1575, 1e-12);
  // No edge left, nothing to cut.
  EXPECT_NEAR(cut.expected_cut({0.5, 0.5, 0.0, 0.0}, kSplit), 0.0, 1e-15);
}

TEST(EdgeCut, TheOffsetTakesOutTheDiscountEveryEdgeGets) {
  pomdp::ObjectProblemData d = testing::four_objects();
  // Pure noise, every row (0.7, 0.3): λ (1, 3/7) for all, m(y)² = 9/49 = λλ' on every edge: 0.
  // (The plain soft cut by P(o|k) P(o|k') would count 1 - 0.49 or 1 - 0.09 of every edge.)
  d.observation_table[kSplit] = {{0.7, 0.3}, {0.7, 0.3}, {0.7, 0.3}, {0.7, 0.3}};
  // y nobody's likeliest symbol: a (0.8, 0.2), b (0.6, 0.4): λ a (1, 0.25), b (1, 2/3); m(x) = 1,
  // m(y) = 2/3. Uniform: x (P 0.7) discounts nothing (1 - 1·1); y (P 0.3) removes
  // 4/9 - 0.25·2/3 = 5/18 of the 0.25: 0.3 · 5/72 = 1/48 (without the offset, 0.3·0.25·5/6).
  d.observation_table[kBins] = {{0.8, 0.2}, {0.8, 0.2}, {0.6, 0.4}, {0.6, 0.4}};
  const EdgeCut cut(d);
  const std::vector<double> uniform{0.25, 0.25, 0.25, 0.25};
  EXPECT_NEAR(cut.expected_cut(uniform, kSplit), 0.0, 1e-15);
  EXPECT_NEAR(cut.expected_cut(uniform, kBins), 1.0 / 48, 1e-12);
}

TEST(EdgeCut, NoiseFreeRowsCutLikeEc2) {
  // Bins without error: x rules out b1, b2 and y a1, a2, so every edge is cut whatever is heard.
  pomdp::ObjectProblemData d = testing::four_objects();
  d.observation_table[kBins] = {{1, 0}, {1, 0}, {0, 1}, {0, 1}};
  d.sensing[kSplit].collision_probability = 1.0;  // never heard: nothing cut
  const EdgeCut cut(d);
  EXPECT_NEAR(cut.expected_cut({0.25, 0.25, 0.25, 0.25}, kBins), 0.25, 1e-15);
  EXPECT_NEAR(cut.expected_cut({0.4, 0.3, 0.2, 0.1}, kBins), 0.21, 1e-15);
  EXPECT_EQ(cut.expected_cut({0.25, 0.25, 0.25, 0.25}, kSplit), 0.0);
}

}  // namespace
}  // namespace echoplan::solvers
