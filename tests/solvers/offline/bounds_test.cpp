// The pieces the solver is built from: alpha-vector pruning, sawtooth interpolation, initial
// bounds.
#include <gtest/gtest.h>

#include "solvers/offline/alpha_vector_set.h"
#include "solvers/offline/belief_expansion.h"
#include "solvers/offline/initial_bounds.h"
#include "solvers/offline/sawtooth_upper_bound.h"
#include "test_problems.h"

namespace echoplan::solvers::offline {
namespace {

TEST(AlphaVectorSet, PrunesPointwiseDominatedVectors) {
  AlphaVectorSet set;
  EXPECT_TRUE(set.add({0, {1.0, 1.0}}));
  EXPECT_FALSE(set.add({1, {0.5, 1.0}}));  // dominated by the first
  EXPECT_TRUE(set.add({2, {0.0, 3.0}}));   // better at the right corner
  EXPECT_EQ(set.size(), 2u);
  EXPECT_TRUE(set.add({3, {2.0, 1.0}}));  // dominates the first, which goes
  ASSERT_EQ(set.size(), 2u);
  EXPECT_EQ(set.best_action({1.0, 0.0}), 3);
  EXPECT_EQ(set.best_action({0.0, 1.0}), 2);
  EXPECT_DOUBLE_EQ(set.value({0.5, 0.5}), 1.5);
}

TEST(SawtoothUpperBound, InterpolatesBetweenCornersAndPoints) {
  // Corners 10 and 20 (from one FIB vector); a point at the middle with value 5.
  SawtoothUpperBound bound({{10.0, 20.0}}, 100.0);
  EXPECT_DOUBLE_EQ(bound.value({0.5, 0.5}), 15.0);
  EXPECT_TRUE(bound.add({0.5, 0.5}, 5.0));
  EXPECT_DOUBLE_EQ(bound.value({0.5, 0.5}), 5.0);
  // At (0.75, 0.25): corners give 12.5; ratio min(0.75/0.5, 0.25/0.5) = 0.5; 12.5 + 0.5 * (5 - 15).
  EXPECT_DOUBLE_EQ(bound.value({0.75, 0.25}), 7.5);
  EXPECT_DOUBLE_EQ(bound.value({1.0, 0.0}), 10.0);
  // A point no better than the bound is not kept.
  EXPECT_FALSE(bound.add({0.75, 0.25}, 8.0));
  EXPECT_EQ(bound.num_points(), 1u);
  // A corner update lowers the corner and what is interpolated from it.
  EXPECT_TRUE(bound.add({1.0, 0.0}, 6.0));
  EXPECT_DOUBLE_EQ(bound.value({1.0, 0.0}), 6.0);
  // Corners now 6, 20: at (0.75, 0.25) 9.5 + 0.5 * (5 - 13) = 5.5.
  EXPECT_DOUBLE_EQ(bound.value({0.75, 0.25}), 5.5);
}

TEST(SawtoothUpperBound, PruneKeepsTheBoundAndDropsImpliedPoints) {
  SawtoothUpperBound bound({{10.0, 10.0}}, 100.0);
  ASSERT_TRUE(bound.add({0.5, 0.5}, 4.0));
  ASSERT_TRUE(bound.add({0.25, 0.75}, 5.0));  // the first point implies 7 here, so it is kept
  // Lower the middle so the second point is implied: at (0.25, 0.75) 10 + 0.5 * (0 - 10) = 5.
  ASSERT_TRUE(bound.add({0.5, 0.5}, 0.0));
  const double before = bound.value({0.3, 0.7});
  bound.prune();
  EXPECT_EQ(bound.num_points(), 1u);
  EXPECT_DOUBLE_EQ(bound.value({0.3, 0.7}), before);
}

TEST(InitialBounds, BlindPolicyAndFibOnTiger) {
  const DensePomdp m = make_dense_pomdp(testing::tiger());
  // Listening forever: -1 / (1 - 0.95) = -20 in both states.
  const std::vector<AlphaVector> blind = blind_policy_vectors(m);
  ASSERT_EQ(blind.size(), 3u);
  EXPECT_NEAR(blind[0].values[0], -20.0, 1e-7);
  // Opening left forever: the average over the reset state solves m = -45 + 0.95 m, m = -900;
  // from tiger-left -100 + 0.95 m = -955, from tiger-right 10 + 0.95 m = -845.
  // Tolerance: iteration stops when steps fall below 1e-9, leaving < 1e-9 / (1 - 0.95) = 2e-8.
  EXPECT_NEAR(blind[1].values[0], -955.0, 1e-6);
  EXPECT_NEAR(blind[1].values[1], -845.0, 1e-6);
  // The fast informed bound is an upper bound on V*(uniform) = 19.371 and below the MDP bound
  // 10 / (1 - 0.95) = 200.
  const auto q = fast_informed_bound(m);
  const double fib_uniform =
      std::max({0.5 * (q[0][0] + q[0][1]), 0.5 * (q[1][0] + q[1][1]), 0.5 * (q[2][0] + q[2][1])});
  EXPECT_GE(fib_uniform, 19.371);
  EXPECT_LT(fib_uniform, 200.0);
}

TEST(BeliefExpansion, TigerListenPosterior) {
  const DensePomdp m = make_dense_pomdp(testing::tiger());
  const BeliefExpansion e = expand(m, {0.5, 0.5}, 0);
  EXPECT_DOUBLE_EQ(e.observation_probability[0], 0.5);
  EXPECT_DOUBLE_EQ(e.next_belief[0][0], 0.85);
  // A second "left" after the first: 0.85^2 / (0.85^2 + 0.15^2).
  const BeliefExpansion again = expand(m, e.next_belief[0], 0);
  EXPECT_DOUBLE_EQ(again.next_belief[0][0], 0.85 * 0.85 / (0.85 * 0.85 + 0.15 * 0.15));
  // Opening a door resets the tiger: the child is uniform whatever was heard.
  EXPECT_DOUBLE_EQ(expand(m, {0.9, 0.1}, 1).next_belief[1][0], 0.5);
}

TEST(BeliefExpansion, ImpossibleObservationKeepsThePrediction) {
  const DensePomdp m = make_dense_pomdp(testing::audio_objects());
  // After a sorting action everything is in the terminal state, which only ever emits observation
  // 0.
  const BeliefExpansion e = expand(m, {0.25, 0.25, 0.25, 0.25, 0.0}, testing::kMoveA);
  EXPECT_EQ(e.observation_probability[0], 1.0);
  EXPECT_EQ(e.observation_probability[2], 0.0);
  EXPECT_EQ(e.next_belief[2], (BeliefVector{0, 0, 0, 0, 1}));
}

}  // namespace
}  // namespace echoplan::solvers::offline
