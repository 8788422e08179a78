// expected_discounted_reward(): each step's reward in expectation under its belief, discounted,
// against sums worked out by hand on a two-object problem.
#include "experiment/expected_reward.h"

#include <gtest/gtest.h>

#include "pomdp/tabular_pomdp.h"

namespace echoplan::experiment {
namespace {

// Objects a and b and an absorbing "sorted"; `listen` keeps the object and hears it right 3 times
// in 4, `sort_a` ends the episode: +10 for a, -100 for b. Listening costs 1 (2 for b, so a wrong
// state's reward would show).
pomdp::TabularPomdp two_objects() {
  pomdp::TabularPomdpData d;
  d.state_names = {"a", "b", "sorted"};
  d.action_names = {"listen", "sort_a"};
  d.observation_names = {"heard_a", "heard_b"};
  d.discount = 0.9;
  d.transition = {1, 0, 0, 0, 1, 0, 0, 0, 1,          // listen: stay
                  0, 0, 1, 0, 0, 1, 0, 0, 1};         // sort_a: to sorted
  d.observation = {0.75, 0.25, 0.25, 0.75, 0.5, 0.5,  // listen
                   0.5,  0.5,  0.5,  0.5,  0.5, 0.5};
  d.reward = {-1, 10,    // a
              -2, -100,  // b
              0,  0};    // sorted
  d.start = {0.5, 0.5, 0};
  return pomdp::TabularPomdp(std::move(d));
}

StepRecord step(int action, std::vector<double> belief) {
  StepRecord s;
  s.action = action;
  s.belief = std::move(belief);
  return s;
}

TEST(ExpectedReward, ListenThenSortByHand) {
  const pomdp::TabularPomdp model = two_objects();
  // Listen at (0.5, 0.5): -1.5. Sort at (0.8, 0.2, 0): 8 - 20 = -12, discounted once: -10.8.
  const auto value =
      expected_discounted_reward({step(0, {0.5, 0.5, 0.0}), step(1, {0.8, 0.2, 0.0})}, model);
  ASSERT_TRUE(value.has_value());
  EXPECT_NEAR(*value, -1.5 - 10.8, 1e-12);
}

TEST(ExpectedReward, BeliefOverTheLiveStatesOnly) {
  // A belief that leaves the absorbing state out at the end counts it as 0.
  const pomdp::TabularPomdp model = two_objects();
  const auto value = expected_discounted_reward({step(1, {0.25, 0.75})}, model);
  ASSERT_TRUE(value.has_value());
  EXPECT_NEAR(*value, 0.25 * 10 - 0.75 * 100, 1e-12);
}

TEST(ExpectedReward, NoStepsIsZero) {
  EXPECT_EQ(expected_discounted_reward({}, two_objects()), 0.0);
}

TEST(ExpectedReward, BeliefsThatDoNotFitTheModelGiveNothing) {
  const pomdp::TabularPomdp model = two_objects();
  EXPECT_FALSE(expected_discounted_reward({step(0, {})}, model).has_value());
  EXPECT_FALSE(expected_discounted_reward({step(0, {0.25, 0.25, 0.25, 0.25})}, model).has_value());
}

}  // namespace
}  // namespace echoplan::experiment
