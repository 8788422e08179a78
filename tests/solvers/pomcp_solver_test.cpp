// POMCP on the shipped tiger problem (problems/tiger.pomdp): the decisions its known optimal policy
// makes after growls, the Monte-Carlo backup of the sampled returns, the leaf values it accepts,
// and reproducibility from the seed. (The uniform-belief "listen first" and the tree reuse shared
// with ABT are in search_tree_test.cpp.)
#include "solvers/pomcp_solver.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "../common/source_dir.h"
#include "common/error.h"
#include "pomdp/particle_belief.h"
#include "pomdp/problem.h"

namespace echoplan::solvers {
namespace {

// tiger.pomdp: states tiger-left, tiger-right; actions listen, open-left, open-right; observations
// tiger-left, tiger-right (the side the growl came from). Listening costs 1 and is right 85% of the
// time; opening the tiger's door costs 100, the other door pays 10; discount 0.95.
constexpr int kListen = 0, kOpenLeft = 1, kOpenRight = 2;
constexpr int kHeardLeft = 0, kHeardRight = 1;

pomdp::ModelPtr tiger() {
  return pomdp::load_problem(echoplan::testing::source_dir() + "/problems/tiger.pomdp").model;
}

pomdp::Observation heard(int side) {
  pomdp::Observation o;
  o.index = side;
  return o;
}

// POMCP rooted at the uniform tiger belief, with its own particle belief to follow real steps.
struct TigerRun {
  explicit TigerRun(std::uint64_t seed, SearchOptions options = {})
      : model(tiger()), rng(seed), belief(model, 2000, rng), solver(model, options) {
    solver.reset(belief, rng);
  }
  // Executes `action`, hears `side`, and moves both the belief and the tree on.
  void step(int action, int side) {
    belief.update(action, heard(side), rng);
    solver.update(action, heard(side), belief, rng);
  }
  pomdp::ModelPtr model;
  Rng rng;
  pomdp::ParticleBelief belief;
  PomcpSolver solver;
};

// Growls from `side`, `count` times, each after a search of `episodes` episodes; then a last
// search.
void listen_and_hear(TigerRun& run, int side, int count, int episodes) {
  for (int k = 0; k < count; ++k) {
    run.solver.improve(Budget::episodes(episodes), run.rng);
    run.step(kListen, side);
  }
  run.solver.improve(Budget::episodes(episodes), run.rng);
}

TEST(PomcpSolver, OpensTheOtherDoorAfterThreeConsistentGrowls) {
  // Three growls from the left put P(tiger-left) at 0.85^3 / (0.85^3 + 0.15^3) = 0.9945. Solving
  // the tiger's belief MDP (value iteration on a 20,001-point belief grid, V(uniform) = 19.371 as
  // the file says) gives 27.80 for opening the right door there against 25.41 for listening once
  // more. Several seeds, so a search that only sometimes gets there fails.
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    TigerRun run(seed);
    listen_and_hear(run, kHeardLeft, 3, 4000);
    EXPECT_EQ(run.solver.best_action(), kOpenRight) << "seed " << seed;
  }
}

TEST(PomcpSolver, MirrorsTheDecisionForGrowlsFromTheRight) {
  TigerRun run(4);
  listen_and_hear(run, kHeardRight, 3, 4000);
  EXPECT_EQ(run.solver.best_action(), kOpenLeft);
}

TEST(PomcpSolver, AfterTwoConsistentGrowlsTheDoorTheyCameFromIsWorst) {
  // At P(tiger-left) = 0.97 opening the right door pays 0.97 * 10 - 0.03 * 100 = 6.7 now, the left
  // one 0.97 * (-100) + 0.03 * 10 = -96.7, and both reset the game. (The exact optimum also opens
  // here, by 25.08 against 24.38 for listening; with its optimistic default leaf POMCP rates the
  // two within 0.2 of each other at these budgets, so only the clear comparison is asserted.)
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    TigerRun run(seed);
    listen_and_hear(run, kHeardLeft, 2, 4000);
    const std::vector<double> values = run.solver.root_action_values();
    EXPECT_GT(values[kOpenRight], values[kOpenLeft]) << "seed " << seed;
    EXPECT_NE(run.solver.best_action(), kOpenLeft) << "seed " << seed;
  }
}

TEST(PomcpSolver, ListensAgainAfterContradictoryGrowls) {
  // Left then right: the belief is uniform again, where opening is worth (10 - 100) / 2 = -45 now.
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    TigerRun run(seed);
    run.solver.improve(Budget::episodes(4000), run.rng);
    run.step(kListen, kHeardLeft);
    listen_and_hear(run, kHeardRight, 1, 4000);
    EXPECT_EQ(run.solver.best_action(), kListen) << "seed " << seed;
  }
}

TEST(PomcpSolver, RootValuesAreMeansOfTheSampledReturns) {
  // Depth 1 with the heuristic leaf: every episode is one step, its return r + 0.95 h(s'), and
  // POMCP's action value is the running mean of those returns. The tiger's MDP value h is the same
  // in both states (the problem is symmetric), so listening (reward -1 everywhere) is worth exactly
  // -1 + 0.95 h, and opening the left door averages -100 (tiger left) and 10 (tiger right) over the
  // uniform root particles: -45 + 0.95 h, within sampling error.
  SearchOptions options;
  options.max_depth = 1;
  options.leaf.mode = LeafMode::heuristic;
  options.leaf.expand_after = 1;
  options.exploration = 1000;  // spread the episodes over all three actions
  TigerRun run(9, options);
  run.solver.improve(Budget::episodes(3000), run.rng);

  pomdp::State left, right;
  left.discrete = {0};
  right.discrete = {1};
  const double h = run.model->heuristic_value(left);
  ASSERT_DOUBLE_EQ(h, run.model->heuristic_value(right));
  // Always opening the safe door pays 10 per step: 10 / (1 - 0.95) = 200.
  ASSERT_NEAR(h, 200.0, 1e-3);

  const std::vector<double> values = run.solver.root_action_values();
  ASSERT_EQ(values.size(), 3u);
  EXPECT_NEAR(values[kListen], -1 + 0.95 * h, 1e-9);
  // Each open action gets about 1000 episodes: the mean reward's standard error is 55 / sqrt(1000)
  // = 1.7; 5 standard errors.
  EXPECT_NEAR(values[kOpenLeft], -45 + 0.95 * h, 8.7);
  EXPECT_NEAR(values[kOpenRight], -45 + 0.95 * h, 8.7);
  // A mean of rewards that are -100 or 10 lies between them.
  for (int a : {kOpenLeft, kOpenRight}) {
    EXPECT_GE(values[a] - 0.95 * h, -100 - 1e-9);
    EXPECT_LE(values[a] - 0.95 * h, 10 + 1e-9);
  }
  EXPECT_EQ(run.solver.stats().episodes_total, 3000);
}

TEST(PomcpSolver, RefusesThePolicyLeafOnlyNamingTheAlternatives) {
  SearchOptions options;
  options.leaf.mode = LeafMode::policy;
  try {
    PomcpSolver solver(tiger(), options);
    ADD_FAILURE() << "the policy leaf was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("lookahead"), std::string::npos) << e.what();
  }
  for (LeafMode mode : {LeafMode::lookahead, LeafMode::heuristic, LeafMode::rollout}) {
    options.leaf.mode = mode;
    EXPECT_NO_THROW(PomcpSolver(tiger(), options)) << leaf_mode_name(mode);
  }
}

TEST(PomcpSolver, SameSeedSameRootValuesAcrossRealSteps) {
  auto values_after_a_step = [](std::uint64_t seed) {
    TigerRun run(seed);
    run.solver.improve(Budget::episodes(1500), run.rng);
    std::vector<double> values = run.solver.root_action_values();
    run.step(kListen, kHeardLeft);
    run.solver.improve(Budget::episodes(1500), run.rng);
    const std::vector<double> after = run.solver.root_action_values();
    values.insert(values.end(), after.begin(), after.end());
    return values;
  };
  const std::vector<double> first = values_after_a_step(21);
  EXPECT_EQ(first, values_after_a_step(21));
  EXPECT_NE(first, values_after_a_step(22));
}

}  // namespace
}  // namespace echoplan::solvers
