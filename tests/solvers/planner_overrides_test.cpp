// search_options() and budget(): the problem file's planner settings unless the user overrides
// them.
#include "solvers/planner_overrides.h"

#include <gtest/gtest.h>

#include "common/error.h"

namespace echoplan::solvers {
namespace {

// A problem whose planner section and belief size differ from every built-in default.
pomdp::Problem problem_with(int episodes, double step_ms) {
  pomdp::Problem p;
  p.planner.exploration = 33.0;
  p.planner.depth = 12;
  p.planner.episodes = episodes;
  p.planner.step_ms = step_ms;
  p.belief.particles = 450;
  return p;
}

TEST(PlannerOverrides, NoOverridesGiveTheProblemFilesSettings) {
  const SearchOptions o = search_options({}, problem_with(700, 0));
  EXPECT_EQ(o.exploration, 33.0);
  EXPECT_EQ(o.max_depth, 12);
  EXPECT_EQ(o.root_particles, 450);
  EXPECT_EQ(o.leaf.mode, LeafMode::lookahead);
  EXPECT_EQ(o.leaf.expand_after, LeafOptions{}.expand_after);
  EXPECT_EQ(o.unheard, UnheardOutcomes::share);
  EXPECT_EQ(o.branching.continuous_threshold, 0.0);
}

TEST(PlannerOverrides, EachOverrideWins) {
  PlannerOverrides f;
  f.exploration = 0.0;  // zero is a setting, not "unset"
  f.depth = 3;
  f.leaf = "rollout";
  f.expand_after = 2;
  PlannerOverrides commit;
  commit.leaf = "policy";
  commit.unheard = "commit";
  EXPECT_EQ(search_options(commit, problem_with(700, 0)).unheard, UnheardOutcomes::commit);
  f.root_particles = 20;
  f.branch_threshold = 0.25;
  const SearchOptions o = search_options(f, problem_with(700, 0));
  EXPECT_EQ(o.exploration, 0.0);
  EXPECT_EQ(o.max_depth, 3);
  EXPECT_EQ(o.leaf.mode, LeafMode::rollout);
  EXPECT_EQ(o.leaf.expand_after, 2);
  EXPECT_EQ(o.root_particles, 20);
  EXPECT_EQ(o.branching.continuous_threshold, 0.25);
}

TEST(PlannerOverrides, BadValuesAreInputErrors) {
  const pomdp::Problem p = problem_with(700, 0);
  PlannerOverrides leaf;
  leaf.leaf = "random";
  EXPECT_THROW(search_options(leaf, p), InputError);
  PlannerOverrides depth;
  depth.depth = 0;
  EXPECT_THROW(search_options(depth, p), InputError);
  PlannerOverrides expand;
  expand.expand_after = 0;
  EXPECT_THROW(search_options(expand, p), InputError);
  PlannerOverrides threshold;
  threshold.branch_threshold = -1.0;
  EXPECT_THROW(search_options(threshold, p), InputError);
  PlannerOverrides unheard;
  unheard.leaf = "policy";
  unheard.unheard = "guess";
  EXPECT_THROW(search_options(unheard, p), InputError);
  // Only a leaf that follows the exact belief knows what committing after an outcome is worth.
  unheard.unheard = "commit";
  unheard.leaf = "lookahead";
  EXPECT_THROW(search_options(unheard, p), InputError);
}

void expect_budget(const Budget& b, Budget::Kind kind, std::int64_t amount) {
  EXPECT_EQ(b.kind, kind);
  EXPECT_EQ(b.amount, amount);
}

TEST(PlannerOverrides, BudgetIsTheUsersEpisodesThenStepTimeThenTheProblemFiles) {
  PlannerOverrides episodes;
  episodes.episodes = 50;
  PlannerOverrides ms;
  ms.step_ms = 80;
  PlannerOverrides both = episodes;
  both.step_ms = 80;
  expect_budget(budget(episodes, problem_with(0, 2000)), Budget::Kind::episodes, 50);
  expect_budget(budget(ms, problem_with(700, 0)), Budget::Kind::milliseconds, 80);
  expect_budget(budget(both, problem_with(700, 0)), Budget::Kind::episodes, 50);
  expect_budget(budget({}, problem_with(700, 0)), Budget::Kind::episodes, 700);
  expect_budget(budget({}, problem_with(0, 2000)), Budget::Kind::milliseconds, 2000);
}

}  // namespace
}  // namespace echoplan::solvers
