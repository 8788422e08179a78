// The pieces the solver is built from: initial bounds and belief
// expansion.
#include <gtest/gtest.h>

#include "solvers/offline/belief_expansion.h"
#include "solvers/offline/initial_bounds.h"
#include "test_problems.h"

namespace echoplan::solvers::offline {
namespace {

TEST(InitialBounds, BlindPolicyAndFibOnTiger) {
  const FlatPomdp m = make_flat_pomdp(testing::tiger());
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
  const FlatPomdp m = make_flat_pomdp(testing::tiger());
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
  const FlatPomdp m = make_flat_pomdp(testing::audio_objects());
  // After a sorting action everything is in the terminal state, which only ever emits "none".
  const BeliefExpansion e = expand(m, {0.25, 0.25, 0.25, 0.25, 0.0}, testing::kMoveA);
  EXPECT_EQ(e.observation_probability[testing::kNone], 1.0);
  EXPECT_EQ(e.observation_probability[2], 0.0);
  EXPECT_EQ(e.next_belief[2], (BeliefVector{0, 0, 0, 0, 1}));
}

}  // namespace
}  // namespace echoplan::solvers::offline
