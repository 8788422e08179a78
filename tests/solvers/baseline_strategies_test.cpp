// The five baseline strategies' decisions on the two-object problem
// (tiny_identification_problems.h: tap 0, press 1, shake 2 with accuracies 0.60, 0.85, 0.70; to_a
// 3, to_b 4) and, where the sort is coarser than the identity, the four-object one (split 0, bins
// 1, to_A 2, to_B 3), worked out by hand.
#include "solvers/baseline_strategies.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "common/error.h"
#include "solvers/make_solver.h"
#include "tiny_identification_problems.h"

namespace echoplan::solvers {
namespace {

using testing::GivenBelief;
using testing::model_of;

constexpr int kTap = 0, kPress = 1, kShake = 2, kToA = 3, kToB = 4;

// Runs a strategy: reset at `start`, then one improve() per entry of `steps`, each decision
// followed by an update() to the belief given.
struct StrategyRun {
  std::unique_ptr<Solver> strategy;
  Rng rng{7};

  StrategyRun(const std::string& name, pomdp::ObjectProblemData d, std::vector<double> start)
      : strategy(make_strategy(name, model_of(std::move(d)))) {
    strategy->reset(GivenBelief(std::move(start)), rng);
  }
  int decide() {
    strategy->improve(Budget::episodes(1), rng);
    return strategy->best_action();
  }
  void heard(int action, std::vector<double> belief_after) {
    strategy->update(action, {0, {}}, GivenBelief(std::move(belief_after)), rng);
  }
};

TEST(BaselineStrategies, NamesAndFactory) {
  EXPECT_EQ(strategy_names(),
            (std::vector<std::string>{"all_actions", "best_single", "decision_region",
                                      "information_gain", "random"}));
  EXPECT_TRUE(is_strategy("random"));
  EXPECT_FALSE(is_strategy("abt"));
  for (const std::string& name : strategy_names())
    EXPECT_NE(make_solver(name, model_of(testing::two_objects()), {}), nullptr) << name;
  try {
    make_strategy("greedy", model_of(testing::two_objects()));
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(),
                 "strategy 'greedy' is not one of all_actions, best_single, decision_region, "
                 "information_gain, random");
  }
}

TEST(AllActions, EverySensingActionOnceInOrderThenSort) {
  StrategyRun run("all_actions", testing::two_objects(), {0.5, 0.5});
  EXPECT_EQ(run.decide(), kTap);
  run.heard(kTap, {0.6, 0.4});
  EXPECT_EQ(run.decide(), kPress);
  run.heard(kPress, {0.4, 0.6});
  EXPECT_EQ(run.decide(), kShake);
  run.heard(kShake, {0.3, 0.7});
  EXPECT_EQ(run.decide(), kToB);  // P(to_b right) = 0.7
}

TEST(AllActions, SkipsAnActionWhoseUsesAreSpent) {
  pomdp::ObjectProblemData d = testing::two_objects();
  d.sensing[kPress].uses = 1;
  StrategyRun run("all_actions", d, {0.5, 0.5});
  run.heard(kPress, {0.8, 0.2});  // press performed (its only use) before the strategy's turn
  EXPECT_EQ(run.decide(), kTap);
  run.heard(kTap, {0.8, 0.2});
  EXPECT_EQ(run.decide(), kShake);
  run.heard(kShake, {0.8, 0.2});
  EXPECT_EQ(run.decide(), kToA);
}

TEST(BestSingle, RepeatsTheMostAccurateActionUntilItsUsesRunOut) {
  pomdp::ObjectProblemData d = testing::two_objects();
  for (auto& a : d.sensing) a.uses = 2;
  StrategyRun run("best_single", d, {0.5, 0.5});
  EXPECT_EQ(run.decide(), kPress);  // 0.85 > 0.70 > 0.60
  run.heard(kPress, {0.9, 0.1});
  EXPECT_EQ(run.decide(), kPress);  // confident already, but a limited action is used up
  run.heard(kPress, {0.95, 0.05});
  EXPECT_EQ(run.decide(), kToA);  // press spent; tap and shake are not its business
}

TEST(BestSingle, FollowsTheAccuracyNotTheOrder) {
  pomdp::ObjectProblemData d = testing::two_objects();
  d.observation_table[kShake] = {{0.95, 0.05}, {0.05, 0.95}};  // accuracy 0.95
  d.sensing[kShake].uses = 1;
  StrategyRun run("best_single", d, {0.5, 0.5});
  EXPECT_EQ(run.decide(), kShake);
  run.heard(kShake, {0.05, 0.95});
  EXPECT_EQ(run.decide(), kToB);
}

TEST(BestSingle, WeighsTheCostAgainstTheAccuracy) {
  // Value of one performance then sorting by it: r_a + 0.99 (-100 + 110 accuracy) (strategy
  // measures). Shake (0.70) at cost 1: -23.77. Press (0.85) at cost c: -c - 6.435, worth it while
  // c < 17.335: at 16 press (-22.435) still wins, at 20 (-26.435) shake does.
  pomdp::ObjectProblemData d = testing::two_objects();
  for (auto& a : d.sensing) a.uses = 1;
  d.sensing[kPress].reward = -16.0;
  EXPECT_EQ(StrategyRun("best_single", d, {0.5, 0.5}).decide(), kPress);
  d.sensing[kPress].reward = -20.0;
  StrategyRun run("best_single", d, {0.5, 0.5});
  EXPECT_EQ(run.decide(), kShake);
  run.heard(kShake, {0.3, 0.7});
  EXPECT_EQ(run.decide(), kToB);  // shake spent: the cheap single action, not the accurate one
}

TEST(BestSingle, WithoutALimitRepeatsWhileOneMoreLookIsWorthIt) {
  {
    // Uniform: pressing once more then committing is worth -1 + 0.99·(-6.5) = -7.435 against
    // committing now at 0.5·10 - 0.5·100 = -45.
    StrategyRun run("best_single", testing::two_objects(), {0.5, 0.5});
    EXPECT_EQ(run.decide(), kPress);
    EXPECT_NEAR(run.strategy->root_action_values()[kPress], -7.435, 1e-12);
  }
  // At (0.99, 0.01) no symbol changes the bin: -1 + 0.99·(0.99·10 - 0.01·100) = 7.811 < 8.9.
  StrategyRun run("best_single", testing::two_objects(), {0.99, 0.01});
  EXPECT_EQ(run.decide(), kToA);
}

TEST(InformationGain, CommitsWhenTheObjectIsKnown) {
  StrategyRun run("information_gain", testing::two_objects(), {1.0, 0.0});
  // Commit now: 10. Any sensing action then commit: -1 + 0.99·10 = 8.9.
  EXPECT_EQ(run.decide(), kToA);
  const std::vector<double> values = run.strategy->root_action_values();
  EXPECT_DOUBLE_EQ(values[kToA], 10.0);
  EXPECT_DOUBLE_EQ(values[kToB], -100.0);
  for (int a : {kTap, kPress, kShake}) EXPECT_NEAR(values[a], 8.9, 1e-12);
}

TEST(InformationGain, CommitsWhenNoSymbolWouldChangeTheBin) {
  // (0.99, 0.01): commit 8.9; every action's lookahead -1 + 0.99·8.9 = 7.811 (BestSingle's case).
  StrategyRun run("information_gain", testing::two_objects(), {0.99, 0.01});
  EXPECT_EQ(run.decide(), kToA);
  EXPECT_NEAR(run.strategy->root_action_values()[kPress], 7.811, 1e-12);
}

TEST(InformationGain, SensesWithTheMostInformativeActionPerUnitCost) {
  {
    // Uniform: gains (nats) tap 0.020136, press 0.275396, shake 0.082283 (strategy_measures_test),
    // all at cost 1; every lookahead (press -7.435) beats committing (-45).
    StrategyRun run("information_gain", testing::two_objects(), {0.5, 0.5});
    EXPECT_EQ(run.decide(), kPress);
  }
  // Press costing 4: 0.275396 / 4 = 0.068849 < shake's 0.082283 (its lookahead, -4 + 0.99·(-6.5),
  // still beats -45).
  pomdp::ObjectProblemData d = testing::two_objects();
  d.sensing[kPress].reward = -4.0;
  StrategyRun run("information_gain", d, {0.5, 0.5});
  EXPECT_EQ(run.decide(), kShake);
  EXPECT_NEAR(run.strategy->root_action_values()[kPress], -4 + 0.99 * -6.5, 1e-12);
}

TEST(InformationGain, TheCheapBehaviourWinsExactlyWhenItsGainPerCostIsHigher) {
  // Press tells 0.275396 nats, shake 0.082283 (at cost 1): press stays the choice while its cost is
  // below 0.275396 / 0.082283 = 3.347, then shake is.
  pomdp::ObjectProblemData d = testing::two_objects();
  d.sensing[kPress].reward = -3.3;
  EXPECT_EQ(StrategyRun("information_gain", d, {0.5, 0.5}).decide(), kPress);
  d.sensing[kPress].reward = -3.4;
  EXPECT_EQ(StrategyRun("information_gain", d, {0.5, 0.5}).decide(), kShake);
  // Shake cheaper still (0.5): 0.082283 / 0.5 = 0.164566 beats press at 2, 0.137698.
  d.sensing[kPress].reward = -2.0;
  d.sensing[kShake].reward = -0.5;
  EXPECT_EQ(StrategyRun("information_gain", d, {0.5, 0.5}).decide(), kShake);
}

TEST(InformationGain, SortsWhenEverySensingActionIsSpent) {
  pomdp::ObjectProblemData d = testing::two_objects();
  for (auto& a : d.sensing) a.uses = 1;
  StrategyRun run("information_gain", d, {0.5, 0.5});
  EXPECT_EQ(run.decide(), kPress);
  run.heard(kPress, {0.5, 0.5});
  EXPECT_EQ(run.decide(), kShake);  // press spent: the next most informative
  run.heard(kShake, {0.5, 0.5});
  EXPECT_EQ(run.decide(), kTap);
  run.heard(kTap, {0.4, 0.6});
  EXPECT_EQ(run.decide(), kToB);
}

// The four-object problem at its uniform prior, by hand (strategy_measures_test for the cuts):
//   commit now: to_A or to_B, 0.5·10 - 0.5·100 = -45 (to_A, the first on ties).
//   bins, then commit: either symbol (P 0.5) leaves the heard bin at 0.8: 0.8·10 - 0.2·100 = -12;
//     -1 + 0.99·(-12) = -12.88.
//   split, then commit: either symbol leaves each bin at 0.5: -1 + 0.99·(-45) = -45.55.
//   entropy reduction (nats): split, ln 4 - H(0.5, 0, 0.25, 0.25) = 1.386294 - 1.039721 = 0.346574;
//     bins, ln 2 - H(0.2) = 0.693147 - 0.500402 = 0.192745.
//   edge mass cut: split 0.125, bins 0.1875.
// Both sense (-12.88 > -45); information_gain takes split, decision_region bins.
constexpr int kSplit = 0, kBins = 1, kToBinA = 2, kToBinB = 3;
const std::vector<double> kUniform4{0.25, 0.25, 0.25, 0.25};

TEST(DecisionRegion, CutsBetweenBinsWhereInformationGainTellsObjectsApart) {
  StrategyRun by_region("decision_region", testing::four_objects(), kUniform4);
  StrategyRun by_entropy("information_gain", testing::four_objects(), kUniform4);
  EXPECT_EQ(by_region.decide(), kBins);
  EXPECT_EQ(by_entropy.decide(), kSplit);
  // The same commit rule, so the same values recorded.
  const std::vector<double> values = by_region.strategy->root_action_values();
  EXPECT_NEAR(values[kSplit], -45.55, 1e-12);
  EXPECT_NEAR(values[kBins], -12.88, 1e-12);
  EXPECT_DOUBLE_EQ(values[kToBinA], -45.0);
  EXPECT_DOUBLE_EQ(values[kToBinB], -45.0);
  const std::vector<double> entropy_values = by_entropy.strategy->root_action_values();
  for (int a = 0; a < 4; ++a) EXPECT_EQ(values[a], entropy_values[a]) << a;
}

TEST(DecisionRegion, WeighsTheCutPerUnitCost) {
  // Bins at cost c: 0.1875 / c against split's 0.125, bins while c < 1.5 (its lookahead,
  // -c - 11.88, still beats -45).
  pomdp::ObjectProblemData d = testing::four_objects();
  d.sensing[kBins].reward = -1.4;
  EXPECT_EQ(StrategyRun("decision_region", d, kUniform4).decide(), kBins);
  d.sensing[kBins].reward = -1.6;
  EXPECT_EQ(StrategyRun("decision_region", d, kUniform4).decide(), kSplit);
  // A zero cost counts as 1: free split's 0.125 loses to bins at 1.4 (0.133929); read as free it
  // would always win.
  d.sensing[kSplit].reward = 0.0;
  d.sensing[kBins].reward = -1.4;
  EXPECT_EQ(StrategyRun("decision_region", d, kUniform4).decide(), kBins);
}

TEST(DecisionRegion, CommitsWhenTheBinIsKnownThoughTheObjectIsNot) {
  // (0.5, 0.5, 0, 0): to_A is right for sure, 10; any sensing then to_A, -1 + 0.99·10 = 8.9. Split
  // would still tell a1 from a2 (ln 2 nats), but nothing is left to cut.
  StrategyRun run("decision_region", testing::four_objects(), {0.5, 0.5, 0.0, 0.0});
  EXPECT_EQ(run.decide(), kToBinA);
  EXPECT_DOUBLE_EQ(run.strategy->root_action_values()[kToBinA], 10.0);
  EXPECT_NEAR(run.strategy->root_action_values()[kSplit], 8.9, 1e-12);
}

TEST(DecisionRegion, HonoursUseLimits) {
  pomdp::ObjectProblemData d = testing::four_objects();
  d.sensing[kBins].uses = 1;
  StrategyRun run("decision_region", d, kUniform4);
  EXPECT_EQ(run.decide(), kBins);
  // Bins spent, the belief (as the test gives it) still uniform: only split is available, and
  // split then commit (-45.55) is worth less than committing now (-45).
  run.heard(kBins, kUniform4);
  EXPECT_EQ(run.decide(), kToBinA);
  EXPECT_NEAR(run.strategy->root_action_values()[kSplit], -45.55, 1e-12);
  EXPECT_TRUE(std::isnan(run.strategy->root_action_values()[kBins]));
  // Both spent: sort without weighing anything.
  d.sensing[kSplit].uses = 1;
  StrategyRun spent("decision_region", d, kUniform4);
  spent.heard(kSplit, kUniform4);
  spent.heard(kBins, {0.1, 0.1, 0.4, 0.4});
  EXPECT_EQ(spent.decide(), kToBinB);
}

// The two-object problem where tap tells nothing ([0.5, 0.5] rows: a grasp) and press and shake
// are possible only after it (Model::prerequisites).
pomdp::ObjectProblemData press_and_shake_after_a_tap() {
  pomdp::ObjectProblemData d = testing::two_objects();
  d.observation_table[kTap] = {{0.5, 0.5}, {0.5, 0.5}};
  d.sensing[kPress].prerequisites = d.sensing[kShake].prerequisites = {kTap};
  return d;
}

TEST(Prerequisites, AllActionsTakesAnActionOnceItIsOpen) {
  pomdp::ObjectProblemData d = testing::two_objects();
  d.sensing[kTap].prerequisites = {kShake};  // tap only after shake: shake, then tap, then press
  StrategyRun run("all_actions", d, {0.5, 0.5});
  EXPECT_EQ(run.decide(), kPress);
  run.heard(kPress, {0.8, 0.2});
  EXPECT_EQ(run.decide(), kShake);
  run.heard(kShake, {0.8, 0.2});
  EXPECT_EQ(run.decide(), kTap);
  run.heard(kTap, {0.8, 0.2});
  EXPECT_EQ(run.decide(), kToA);
}

TEST(Prerequisites, BestSingleOpensItsActionFirstAndCountsWhatThatCosts) {
  // press alone: -1 + 0.99·(0.85·10 - 0.15·100) = -7.435, plus the tap it waits for: -8.435;
  // shake: -1 + 0.99·(0.7·10 - 0.3·100) = -23.77, plus the tap: -24.77. Press, after a tap.
  pomdp::ObjectProblemData d = press_and_shake_after_a_tap();
  d.sensing[kPress].uses = 1;
  StrategyRun run("best_single", d, {0.5, 0.5});
  EXPECT_EQ(run.decide(), kTap);
  run.heard(kTap, {0.5, 0.5});
  EXPECT_EQ(run.decide(), kPress);
  run.heard(kPress, {0.9, 0.1});
  EXPECT_EQ(run.decide(), kToA);
  // Only press waits for a tap costing 20: press -27.435, shake alone -23.77. Shake, at once.
  d = testing::two_objects();
  d.sensing[kTap].reward = -20.0;
  d.sensing[kPress].prerequisites = {kTap};
  d.sensing[kShake].uses = 1;
  StrategyRun priced("best_single", d, {0.5, 0.5});
  EXPECT_EQ(priced.decide(), kShake);
}

TEST(Prerequisites, TheGreedyRulesNeverOpenWhatATellNothingActionOpens) {
  // Only the tap is open and it changes no belief: tap then commit is worth the cost less than
  // committing now, so both greedy rules sort at once (to_a, the first on ties), though press
  // after it is worth -1 + 0.99·(-7.435) = -8.36 against -45.
  for (const char* rule : {"information_gain", "decision_region"}) {
    StrategyRun run(rule, press_and_shake_after_a_tap(), {0.5, 0.5});
    EXPECT_EQ(run.decide(), kToA) << rule;
    EXPECT_TRUE(std::isnan(run.strategy->root_action_values()[kPress])) << rule;
    // Once tapped (by someone else), press is open and taken.
    run.heard(kTap, {0.5, 0.5});
    EXPECT_EQ(run.decide(), kPress) << rule;
  }
}

// Decisions of `random` at a fixed belief, with no update (so the choices stay the same).
std::vector<int> random_decisions(const pomdp::ObjectProblemData& d, std::vector<double> belief,
                                  std::uint64_t seed, int n, int spent = -1) {
  const auto strategy = make_strategy("random", model_of(d));
  Rng rng(seed);
  strategy->reset(GivenBelief(belief), rng);
  if (spent >= 0) strategy->update(spent, {0, {}}, GivenBelief(belief), rng);
  std::vector<int> decisions;
  for (int i = 0; i < n; ++i) {
    strategy->improve(Budget::episodes(1), rng);
    decisions.push_back(strategy->best_action());
  }
  return decisions;
}

TEST(Random, ReproducibleForASeed) {
  const auto d = testing::two_objects();
  EXPECT_EQ(random_decisions(d, {0.5, 0.5}, 11, 50), random_decisions(d, {0.5, 0.5}, 11, 50));
  EXPECT_NE(random_decisions(d, {0.5, 0.5}, 11, 50), random_decisions(d, {0.5, 0.5}, 12, 50));
}

TEST(Random, UniformOverTheAvailableSensingActionsAndSortNow) {
  // Four choices at 1/4 each; 4000 draws: sd sqrt(0.25·0.75/4000) = 0.0068, so ±0.03 is 4.4 sd.
  // "Sort now" at (0.2, 0.8) is to_b; to_a never.
  const int n = 4000;
  std::array<int, 5> count{};
  for (int a : random_decisions(testing::two_objects(), {0.2, 0.8}, 5, n)) ++count[a];
  EXPECT_EQ(count[kToA], 0);
  for (int a : {kTap, kPress, kShake, kToB}) EXPECT_NEAR(count[a] / double(n), 0.25, 0.03) << a;
  // Press spent: three choices at 1/3 (sd 0.0075).
  pomdp::ObjectProblemData d = testing::two_objects();
  d.sensing[kPress].uses = 1;
  count = {};
  for (int a : random_decisions(d, {0.2, 0.8}, 6, n, kPress)) ++count[a];
  EXPECT_EQ(count[kPress], 0);
  for (int a : {kTap, kShake, kToB}) EXPECT_NEAR(count[a] / double(n), 1.0 / 3, 0.03) << a;
}

}  // namespace
}  // namespace echoplan::solvers
