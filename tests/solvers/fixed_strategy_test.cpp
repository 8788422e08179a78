// What every baseline strategy shares: sorting to the bin most likely right, counting uses since
// reset(), refusing problems that are not object identification, and the Solver plumbing.
#include "solvers/fixed_strategy.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "../common/source_dir.h"
#include "common/error.h"
#include "pomdp/problem.h"
#include "solvers/baseline_strategies.h"
#include "tiny_identification_problems.h"

namespace echoplan::solvers {
namespace {

using testing::GivenBelief;
using testing::model_of;

TEST(MostLikelyRightSort, CountsTheObjectsEachBinIsRightFor) {
  const pomdp::ObjectProblemData d = testing::three_objects();
  // to_A is right for x only, to_B for y and z.
  // {0.6, 0.2, 0.2}: P(A right) = 0.6 > P(B right) = 0.4, so A, although B has the better expected
  // reward (A: 6 - 20 - 20 = -34; B: -6 + 2 + 2 = -2).
  EXPECT_EQ(most_likely_right_sort(d, {0.6, 0.2, 0.2}), 0);
  // {0.4, 0.3, 0.3}: P(B right) = 0.6.
  EXPECT_EQ(most_likely_right_sort(d, {0.4, 0.3, 0.3}), 1);
  // {0.5, 0.25, 0.25}: 0.5 each, a tie: the first bin.
  EXPECT_EQ(most_likely_right_sort(d, {0.5, 0.25, 0.25}), 0);
}

TEST(MostLikelyRightSort, ABinCountsForEveryObjectItIsBestFor) {
  pomdp::ObjectProblemData d = testing::three_objects();
  d.sorting_reward = {{10, -100, 10}, {-10, 10, 10}};  // z is right in both bins
  // A: x + z = 0.2 + 0.45 = 0.65; B: y + z = 0.35 + 0.45 = 0.8.
  EXPECT_EQ(most_likely_right_sort(d, {0.2, 0.35, 0.45}), 1);
  // A: 0.5 + 0.3 = 0.8; B: 0.2 + 0.3 = 0.5.
  EXPECT_EQ(most_likely_right_sort(d, {0.5, 0.2, 0.3}), 0);
}

TEST(FixedStrategy, EachStrategySortsToTheBinMostLikelyRightWhenNothingIsLeftToSense) {
  pomdp::ObjectProblemData d = testing::three_objects();
  d.sensing[0].uses = 1;
  // The one listen is spent: all four strategies must sort, to A at {0.6, 0.2, 0.2} (action 1)
  // and to B at {0.4, 0.3, 0.3} (action 2).
  for (const std::string& name : strategy_names()) {
    const auto strategy = make_strategy(name, model_of(d));
    Rng rng(3);
    strategy->reset(GivenBelief({1.0 / 3, 1.0 / 3, 1.0 / 3}), rng);
    strategy->update(0, {0, {}}, GivenBelief({0.6, 0.2, 0.2}), rng);
    strategy->improve(Budget::episodes(1), rng);
    EXPECT_EQ(strategy->best_action(), 1) << name;
    strategy->reset(GivenBelief({1.0 / 3, 1.0 / 3, 1.0 / 3}), rng);
    strategy->update(0, {0, {}}, GivenBelief({0.4, 0.3, 0.3}), rng);
    strategy->improve(Budget::episodes(1), rng);
    EXPECT_EQ(strategy->best_action(), 2) << name;
  }
}

TEST(FixedStrategy, ResetForgetsTheUsesOfThePreviousEpisode) {
  pomdp::ObjectProblemData d = testing::two_objects();
  for (auto& a : d.sensing) a.uses = 1;
  const auto strategy = make_strategy("all_actions", model_of(d));
  Rng rng(1);
  const GivenBelief uniform({0.5, 0.5});
  strategy->reset(uniform, rng);
  for (int a = 0; a < 3; ++a) strategy->update(a, {a % 2, {}}, uniform, rng);
  strategy->improve(Budget::episodes(1), rng);
  EXPECT_EQ(strategy->best_action(), 3);  // all used: sort (a tie at 0.5: the first bin)
  strategy->reset(uniform, rng);
  strategy->improve(Budget::episodes(1), rng);
  EXPECT_EQ(strategy->best_action(), 0);
}

TEST(FixedStrategy, NoSearchNoTreeAndADecisionOnlyAfterImprove) {
  const auto strategy = make_strategy("all_actions", model_of(testing::two_objects()));
  Rng rng(1);
  strategy->reset(GivenBelief({0.5, 0.5}), rng);
  EXPECT_THROW(strategy->best_action(), std::logic_error);
  strategy->improve(Budget::milliseconds(5000), rng);  // returns at once: nothing to search
  EXPECT_EQ(strategy->best_action(), 0);
  const SolverStats stats = strategy->stats();
  EXPECT_EQ(stats.episodes_total, 0);
  EXPECT_EQ(stats.episodes_last, 0);
  EXPECT_EQ(stats.belief_nodes, 0);
  const std::vector<double> values = strategy->root_action_values();
  ASSERT_EQ(values.size(), 5u);
  for (double v : values) EXPECT_TRUE(std::isnan(v));
}

TEST(FixedStrategy, RefusesProblemsThatAreNotObjectIdentification) {
  const pomdp::Problem tiger =
      pomdp::load_problem(echoplan::testing::source_dir() + "/problems/tiger.pomdp");
  for (const std::string& name : strategy_names()) {
    try {
      make_strategy(name, tiger.model);
      FAIL() << "no InputError for " << name;
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("strategy '" + name + "' needs an object-identification problem"),
                std::string::npos)
          << what;
    }
  }
}

}  // namespace
}  // namespace echoplan::solvers
