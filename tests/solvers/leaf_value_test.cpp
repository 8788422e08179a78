#include "solvers/leaf_value.h"

#include <gtest/gtest.h>

#include "../common/source_dir.h"
#include "common/error.h"
#include "pomdp/problem.h"

namespace echoplan::solvers {
namespace {

// The report's shipped problem: objects 0 and 2 belong at A, 1 and 3 at B; sorting right earns 10,
// wrong -100; sensing costs 1; discount 0.99; the heuristic of a known object is 10 (sort it now).
std::shared_ptr<const pomdp::Model> report_model() {
  return pomdp::load_problem(echoplan::testing::source_dir() + "/problems/audio_objects.yaml")
      .model;
}

// The full model state of object k at the start of an episode (arm joints and offset filled in).
pomdp::State object(int k) { return report_model()->tabular_state(k); }

// What an episode reaching a leaf at depth 1 with object k's state adds, valued by `mode`.
void add(LeafEstimate& leaf, LeafMode mode, const pomdp::ModelPtr& model, int k, int steps_left,
         Rng& rng) {
  const pomdp::State state = object(k);
  make_leaf_value({mode, 1}, model, LeafUse::state_tree)
      ->add(leaf, LeafVisit{*model, state, 1, steps_left}, rng);
}

TEST(LeafEstimate, LookaheadCommitsWhenCertain) {
  const auto shipped = report_model();
  Rng rng(1);
  LeafEstimate leaf;
  add(leaf, LeafMode::lookahead, shipped, 0, 10, rng);
  add(leaf, LeafMode::lookahead, shipped, 2, 10, rng);
  // Objects 0 and 2 both belong at A: committing earns 10, more than sensing (-1 + 0.99 * 10).
  EXPECT_DOUBLE_EQ(leaf.value(), 10.0);
}

TEST(LeafEstimate, LookaheadSensesWhenTheGroupIsUncertain) {
  const auto shipped = report_model();
  Rng rng(1);
  LeafEstimate leaf;
  add(leaf, LeafMode::lookahead, shipped, 0, 10, rng);
  add(leaf, LeafMode::lookahead, shipped, 1, 10, rng);
  // Either sort is right half the time: (10 - 100) / 2 = -45; sensing then h = 10 is -1 + 9.9.
  EXPECT_DOUBLE_EQ(leaf.value(), -1.0 + 0.99 * 10.0);
}

TEST(LeafEstimate, HeuristicAveragesTheModelHeuristic) {
  const auto shipped = report_model();
  Rng rng(1);
  LeafEstimate leaf;
  add(leaf, LeafMode::heuristic, shipped, 0, 10, rng);
  add(leaf, LeafMode::heuristic, shipped, 1, 10, rng);
  EXPECT_DOUBLE_EQ(leaf.value(), 10.0);
  EXPECT_EQ(leaf.count(), 2);
}

TEST(LeafEstimate, RandomRolloutIsPoorOnTheReportsProblem) {
  // The reason lookahead is the default: random play sorts wrongly half of the time. Its mean over
  // many rollouts lies far below 0. Exactly: each step senses (-1, continue) or sorts (mean -45)
  // with probability 1/2, so V = 0.5 (-45) + 0.5 (-1 + 0.99 V), V = -23 / 0.505.
  const auto shipped = report_model();
  Rng rng(3);
  LeafEstimate leaf;
  for (int i = 0; i < 4000; ++i) add(leaf, LeafMode::rollout, shipped, i % 4, 50, rng);
  // Returns are about -100 or +10 (sd ~55), so the standard error is ~0.9; the band is 5 of them.
  EXPECT_NEAR(leaf.value(), -23.0 / 0.505, 4.5);
}

TEST(LeafMode, ParsesNamesAndRejectsOthers) {
  EXPECT_EQ(parse_leaf_mode("rollout"), LeafMode::rollout);
  EXPECT_STREQ(leaf_mode_name(parse_leaf_mode("lookahead")), "lookahead");
  EXPECT_THROW(parse_leaf_mode("random"), InputError);
}

}  // namespace
}  // namespace echoplan::solvers
