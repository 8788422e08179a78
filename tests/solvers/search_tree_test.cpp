// ABT and POMCP over the shared belief tree, on the shipped problems (problems/audio_objects.yaml,
// problems/tiger.pomdp) with the shipped ParticleBelief: tree reuse and pruning, determinism, the
// optimal first action on the report's problem, option validation.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "../common/source_dir.h"
#include "common/error.h"
#include "pomdp/particle_belief.h"
#include "pomdp/problem.h"
#include "solvers/abt_solver.h"
#include "solvers/pomcp_solver.h"

namespace echoplan::solvers {
namespace {

pomdp::ModelPtr shipped(const std::string& file) {
  return pomdp::load_problem(echoplan::testing::source_dir() + "/problems/" + file).model;
}
pomdp::ModelPtr report_model() { return shipped("audio_objects.yaml"); }
// Action indices: the report's problem lists its sensing actions, then its sorting actions; the
// tiger file lists listen first.
constexpr int kSlide = 0, kStrike = 1, kMoveToA = 2;
constexpr int kListen = 0;

enum class Kind { abt, pomcp };

std::unique_ptr<TreeSearchSolver> make_solver(Kind kind, pomdp::ModelPtr model,
                                              SearchOptions options = {}) {
  if (kind == Kind::abt) return std::make_unique<AbtSolver>(std::move(model), options);
  return std::make_unique<PomcpSolver>(std::move(model), options);
}

// A solver rooted at a fresh particle belief over `model`: where every test starts.
struct Rooted {
  Rooted(Kind kind, pomdp::ModelPtr m, std::uint64_t seed, int particles,
         SearchOptions options = {})
      : model(m), rng(seed), belief(m, particles, rng), solver(make_solver(kind, m, options)) {
    solver->reset(belief, rng);
  }
  pomdp::ModelPtr model;
  Rng rng;
  pomdp::ParticleBelief belief;
  std::unique_ptr<TreeSearchSolver> solver;
};

class TreeSolvers : public ::testing::TestWithParam<Kind> {};

TEST_P(TreeSolvers, UpdateKeepsTheTakenBranchAndFreesTheRest) {
  Rooted t(GetParam(), report_model(), 7, 1000);
  auto& solver = t.solver;
  auto& rng = t.rng;
  auto& belief = t.belief;
  solver->improve(Budget::episodes(3000), rng);

  const SolverStats before = solver->stats();
  // The live-node counters agree with a walk of the tree: nothing leaks, nothing is double-counted.
  EXPECT_EQ(before.belief_nodes, solver->reachable_nodes().belief);
  EXPECT_EQ(before.action_nodes, solver->reachable_nodes().action);

  pomdp::Observation heard;
  heard.index = 1;
  const int action = kStrike;
  const std::int64_t kept = solver->subtree_belief_nodes(action, heard);
  ASSERT_GT(kept, 10) << "3000 episodes should have grown a real subtree under (strike, O1)";
  ASSERT_LT(kept, before.belief_nodes - 10) << "the siblings hold nodes too";

  belief.update(action, heard, rng);
  solver->update(action, heard, belief, rng);
  const SolverStats after = solver->stats();
  // Exactly the kept subtree survives: the counters fall by everything else, so it was freed.
  EXPECT_EQ(after.belief_nodes, kept);
  EXPECT_EQ(after.belief_nodes, solver->reachable_nodes().belief);
  EXPECT_EQ(after.action_nodes, solver->reachable_nodes().action);
  EXPECT_EQ(after.episodes_total, before.episodes_total);

  // Planning continues from the kept tree: the node count grows from there.
  solver->improve(Budget::episodes(500), rng);
  EXPECT_GT(solver->stats().belief_nodes, kept);
}

TEST_P(TreeSolvers, SmallRootIsReplenishedFromTheRealBelief) {
  SearchOptions options;
  options.root_particles = 300;
  options.min_root_particles = 1000000;  // every kept root counts as too small
  Rooted t(GetParam(), report_model(), 11, 500, options);
  auto& solver = t.solver;
  auto& rng = t.rng;
  auto& belief = t.belief;
  EXPECT_EQ(solver->stats().root_particles, 300);
  solver->improve(Budget::episodes(200), rng);
  pomdp::Observation heard;
  heard.index = 3;
  belief.update(kSlide, heard, rng);
  solver->update(kSlide, heard, belief, rng);
  EXPECT_EQ(solver->stats().root_particles, 300);
}

TEST_P(TreeSolvers, UntriedActionStartsAFreshRootFromTheRealBelief) {
  SearchOptions options;
  options.root_particles = 150;
  Rooted t(GetParam(), report_model(), 5, 200, options);
  auto& solver = t.solver;
  auto& rng = t.rng;
  auto& belief = t.belief;
  solver->improve(Budget::episodes(2), rng);  // tries slide, then strike: nothing under move_to_A
  ASSERT_TRUE(std::isnan(solver->root_action_values()[kMoveToA]));
  pomdp::Observation heard;
  heard.index = 0;
  solver->update(kMoveToA, heard, belief, rng);
  EXPECT_EQ(solver->stats().belief_nodes, 1);
  EXPECT_EQ(solver->stats().action_nodes, 0);
  EXPECT_EQ(solver->stats().root_particles, 150);
}

TEST_P(TreeSolvers, SameSeedSameSearch) {
  auto model = report_model();
  auto run = [&](std::uint64_t seed) {
    Rooted t(GetParam(), model, seed, 1000);
    t.solver->improve(Budget::episodes(2000), t.rng);
    return std::make_pair(t.solver->root_action_values(), t.solver->stats().belief_nodes);
  };
  const auto first = run(42);
  EXPECT_EQ(first, run(42));
  EXPECT_NE(first, run(43));
}

TEST_P(TreeSolvers, TimeBudgetRunsAtLeastOneEpisode) {
  Rooted t(GetParam(), report_model(), 1, 100);
  auto& solver = t.solver;
  auto& rng = t.rng;
  solver->improve(Budget::milliseconds(1), rng);
  EXPECT_GE(solver->stats().episodes_last, 1);
  EXPECT_NO_THROW(solver->best_action());
}

TEST_P(TreeSolvers, TigerListensFirst) {
  // From the uniform belief, opening a door is worth (10 - 100) / 2 = -45; listening is optimal.
  Rooted t(GetParam(), shipped("tiger.pomdp"), 3, 1000);
  auto& solver = t.solver;
  auto& rng = t.rng;
  solver->improve(Budget::episodes(5000), rng);
  EXPECT_EQ(solver->best_action(), kListen);
}

INSTANTIATE_TEST_SUITE_P(AbtAndPomcp, TreeSolvers, ::testing::Values(Kind::abt, Kind::pomcp),
                         [](const auto& param_info) {
                           return param_info.param == Kind::abt ? "abt" : "pomcp";
                         });

TEST(AbtSolver, PrefersStrikeFirstOnTheReportsProblem) {
  // The optimal first action from the uniform belief is the strike (worth 2.9534 against 2.835 for
  // the slide, DESIGN.md). The gap is small, so each search gets a decent budget; requiring every
  // one of 5 independent seeds to pick the strike makes a planner indifferent between the two fail
  // with probability 1 - 1/32.
  auto model = report_model();
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    Rooted t(Kind::abt, model, seed, 1000);
    t.solver->improve(Budget::episodes(20000), t.rng);
    EXPECT_EQ(t.solver->best_action(), kStrike) << "seed " << seed;
  }
}

TEST(SearchOptions, RejectsNonsense) {
  auto model = report_model();
  SearchOptions options;
  options.max_depth = 0;
  EXPECT_THROW(AbtSolver(model, options), InputError);
  options = {};
  options.exploration = -1;
  EXPECT_THROW(PomcpSolver(model, options), InputError);
  options = {};
  options.leaf.expand_after = 0;
  EXPECT_THROW(AbtSolver(model, options), InputError);
  Rng rng(1);
  AbtSolver solver(model, {});
  pomdp::ParticleBelief belief(model, 10, rng);
  solver.reset(belief, rng);
  EXPECT_THROW(solver.improve(Budget::episodes(0), rng), InputError);
}

}  // namespace
}  // namespace echoplan::solvers
