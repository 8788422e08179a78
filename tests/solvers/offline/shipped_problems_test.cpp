// The solver on the problem files shipped in problems/, through the pomdp module's loader.
#include <gtest/gtest.h>

#include "../../common/source_dir.h"
#include "pomdp/problem.h"
#include "solvers/offline/point_based_solver.h"

namespace echoplan::solvers::offline {
namespace {

std::shared_ptr<const FlatPomdp> load_tables(const std::string& name) {
  const std::string path = echoplan::testing::source_dir() + "/problems/" + name;
  const pomdp::Problem problem = pomdp::load_problem(path);
  return std::make_shared<const FlatPomdp>(make_flat_pomdp(*problem.model->tabular(), path));
}

TEST(ShippedProblems, TigerFileReproducesItsKnownValue) {
  SolverOptions options;
  options.epsilon = 2e-5;  // gap <= 3.9e-4 at V* ~ 19.37
  PointBasedSolver solver(load_tables("tiger.pomdp"), options);
  const SolverProgress result = solver.solve();
  ASSERT_TRUE(result.converged);
  // 19.371 is rounded to 3 decimals: the true value is within 5e-4 of it.
  EXPECT_LE(result.root.lower, 19.371 + 5e-4);
  EXPECT_GE(result.root.upper, 19.371 - 5e-4);
  EXPECT_NEAR(result.root.lower, 19.371, 1e-3);
  EXPECT_NEAR(result.root.upper, 19.371, 1e-3);
}

// The YAML problem and its .pomdp transcription are the same tables, so the same trials give the
// same bounds, bit for bit.
TEST(ShippedProblems, ReportProblemYamlAndPomdpAgree) {
  const auto yaml = load_tables("audio_objects.yaml");
  const auto cassandra = load_tables("audio_objects.pomdp");
  ASSERT_EQ(yaml->num_states, cassandra->num_states);
  ASSERT_EQ(yaml->num_actions, cassandra->num_actions);
  SolverOptions options;
  options.max_trials = 100;
  options.time_limit_seconds = 0.0;
  PointBasedSolver a(yaml, options), b(cassandra, options);
  const SolverProgress ra = a.solve(), rb = b.solve();
  EXPECT_EQ(ra.root.lower, rb.root.lower);
  EXPECT_EQ(ra.root.upper, rb.root.upper);
  // The exact value's interval [2.95334, 2.95348] (DESIGN.md) must lie inside the bounds: 100
  // trials leave them far wider than it (the ends were swapped here before, which let a lower bound
  // inside the interval pass).
  EXPECT_LE(ra.root.lower, 2.95334);
  EXPECT_GE(ra.root.upper, 2.95348);
  EXPECT_GT(ra.root.upper - ra.root.lower, 2.95348 - 2.95334);
  EXPECT_EQ(a.best_action(yaml->initial_belief), 1);  // strike
}

}  // namespace
}  // namespace echoplan::solvers::offline
