// solvers::make_solver(overrides, problem, path) (solvers/solver_factory.h): the one factory builds
// each solver by name with the options and budget the overrides ask for, the offline one from a
// policy file, and refuses what would be ignored or unknown. Here rather than in solvers_tests
// because the factory lives in the offline solver's library.
#include "solvers/solver_factory.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <memory>
#include <string>

#include "../../common/source_dir.h"
#include "common/error.h"
#include "pomdp/exact_belief.h"
#include "solvers/offline/policy_file.h"

namespace echoplan::solvers {
namespace {

pomdp::Problem report_problem() {
  return pomdp::load_problem(echoplan::testing::source_dir() + "/problems/audio_objects.yaml");
}

TEST(SolverFactory, BuildsAnOnlineSolverWithTheOverridesOptionsAndBudget) {
  const pomdp::Problem problem = report_problem();
  PlannerOverrides overrides;
  overrides.solver = "pomcp";
  overrides.episodes = 123;
  overrides.depth = 7;
  const BuiltSolver built = make_solver(overrides, problem, "seed");
  EXPECT_EQ(built.name, "pomcp");
  EXPECT_EQ(built.budget.kind, Budget::Kind::episodes);
  EXPECT_EQ(built.budget.amount, 123);
  EXPECT_EQ(built.options.max_depth, 7);
  EXPECT_EQ(built.options.leaf.mode, LeafMode::lookahead);
  ASSERT_NE(built.solver, nullptr);
  // The episode budget is the one the solver spends.
  pomdp::ExactBelief belief(problem.model);
  Rng rng(1);
  built.solver->reset(belief, rng);
  built.solver->improve(built.budget, rng);
  EXPECT_EQ(built.solver->stats().episodes_total, 123);
}

TEST(SolverFactory, TakesTheProblemFilesSolverWhenNoneIsNamed) {
  const pomdp::Problem problem = report_problem();
  const BuiltSolver built = make_solver(PlannerOverrides{}, problem, "seed");
  EXPECT_EQ(built.name, problem.planner.solver);
  EXPECT_NE(built.solver, nullptr);
}

TEST(SolverFactory, BuildsTheOfflineSolverFromAPolicyFile) {
  const pomdp::Problem problem = report_problem();
  auto flat = std::make_shared<const offline::FlatPomdp>(
      offline::make_flat_pomdp(*problem.model->tabular()));
  offline::SolverOptions options;
  options.max_trials = 20;
  offline::PointBasedSolver solved(flat, options);
  solved.solve();
  const std::string path =
      (std::filesystem::temp_directory_path() / "echoplan_solver_factory_policy.json").string();
  offline::save_policy(solved, path);
  PlannerOverrides overrides;
  overrides.solver = "offline";
  overrides.policy = path;
  const BuiltSolver built = make_solver(overrides, problem, "seed");
  std::filesystem::remove(path);
  EXPECT_EQ(built.name, "offline");
  ASSERT_NE(built.solver, nullptr);
  pomdp::ExactBelief belief(problem.model);
  Rng rng(1);
  built.solver->reset(belief, rng);
  EXPECT_EQ(built.solver->best_action(), solved.best_action(flat->initial_belief));
}

TEST(SolverFactory, RefusesAPolicyForAnOnlineSolverAndUnknownNames) {
  const pomdp::Problem problem = report_problem();
  PlannerOverrides overrides;
  overrides.solver = "abt";
  overrides.policy = "policy.json";
  EXPECT_THROW(make_solver(overrides, problem, "seed"), InputError);
  overrides.policy.clear();
  overrides.solver = "ABT";
  EXPECT_THROW(make_solver(overrides, problem, "seed"), InputError);
}

}  // namespace
}  // namespace echoplan::solvers
