// The solver's alpha vectors used as a policy: the value it really earns, and its file round trip.
#include "solvers/offline/alpha_vector_policy.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "common/error.h"
#include "common/rng.h"
#include "solvers/offline/point_based_solver.h"
#include "solvers/offline/policy_file.h"
#include "test_problems.h"

namespace echoplan::solvers::offline {
namespace {

// Draws an index from `probabilities` with one uniform number.
int draw(const std::vector<double>& probabilities, Rng& rng) {
  double u = uniform01(rng);
  for (std::size_t i = 0; i + 1 < probabilities.size(); ++i) {
    if (u < probabilities[i]) return static_cast<int>(i);
    u -= probabilities[i];
  }
  return static_cast<int>(probabilities.size()) - 1;
}

class SolvedSeedProblem : public ::testing::Test {
 protected:
  void SetUp() override {
    SolverOptions options;
    options.max_trials = 300;  // a fixed amount of work: the same vectors on every machine
    solver = std::make_unique<PointBasedSolver>(
        std::make_shared<const DensePomdp>(make_dense_pomdp(model)), options);
    result = solver->solve();
  }
  testing::TableModel model = testing::audio_objects();
  std::unique_ptr<PointBasedSolver> solver;
  SolverProgress result;
};

// Simulating the policy against the true tables must earn its lower bound (and cannot beat V*):
// the mean over many episodes lies within 4 standard errors of [lower, upper].
TEST_F(SolvedSeedProblem, PolicyEarnsItsLowerBoundInSimulation) {
  AlphaVectorPolicy policy(solver->pomdp_ptr(), solver->lower_bound());
  Rng rng(derive_seed(2024, {3}));
  const int episodes = 20000;
  double sum = 0.0, sum_sq = 0.0;
  for (int e = 0; e < episodes; ++e) {
    policy.reset();
    int state = draw(model.b0, rng);
    double total = 0.0, weight = 1.0;
    for (int step = 0; step < 1000 && !model.is_terminal[state]; ++step) {
      const int a = policy.best_action();
      total += weight * model.R[state][a];
      weight *= model.gamma;
      state = draw(model.T[a][state], rng);
      const int o = draw(model.Z[a][state], rng);
      ASSERT_TRUE(policy.update(a, o));
    }
    sum += total;
    sum_sq += total * total;
  }
  const double mean = sum / episodes;
  const double stderr_mean = std::sqrt((sum_sq / episodes - mean * mean) / episodes);
  EXPECT_GE(mean, result.root.lower - 4 * stderr_mean);
  EXPECT_LE(mean, result.root.upper + 4 * stderr_mean);
}

TEST_F(SolvedSeedProblem, FirstActionIsStrikeAndBeliefFollowsObservations) {
  AlphaVectorPolicy policy(solver->pomdp_ptr(), solver->lower_bound());
  policy.reset();
  EXPECT_EQ(policy.best_action(), testing::kStrike);
  EXPECT_NEAR(policy.value(), result.root.lower, 1e-12);
  // Strike heard as object 3: P(o=3 | s) = (0.05, 0.05, 0.11, 0.67) normalised.
  ASSERT_TRUE(policy.update(testing::kStrike, 3));
  EXPECT_NEAR(policy.belief()[3], 0.67 / (0.05 + 0.05 + 0.11 + 0.67), 1e-12);
}

TEST_F(SolvedSeedProblem, PolicyFileRoundTrip) {
  const auto path = std::filesystem::temp_directory_path() / "echoplan_offline_policy_test.json";
  save_policy(*solver, path.string());
  const AlphaVectorSet loaded = load_policy(path.string(), solver->pomdp());
  ASSERT_EQ(loaded.size(), solver->lower_bound().size());
  const BeliefVector b0 = solver->pomdp().initial_belief;
  EXPECT_DOUBLE_EQ(loaded.value(b0), solver->lower_bound().value(b0));
  EXPECT_EQ(loaded.best_action(b0), testing::kStrike);
  std::filesystem::remove(path);
}

// Writes `text` to a temporary file and expects load_policy to reject it with `line` and a message
// containing `fragment`.
void expect_rejected(const std::string& text, int line, const std::string& fragment) {
  const auto path = std::filesystem::temp_directory_path() / "echoplan_offline_bad_policy.json";
  std::ofstream(path) << text;
  const DensePomdp m = make_dense_pomdp(testing::tiger());
  try {
    load_policy(path.string(), m);
    ADD_FAILURE() << "accepted: " << text;
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), path.string());
    EXPECT_EQ(e.line(), line);
    EXPECT_NE(e.problem().find(fragment), std::string::npos) << e.what();
  }
  std::filesystem::remove(path);
}

TEST(PolicyFile, RejectsBadFiles) {
  const std::string head =
      R"({"format": "echoplan-alpha-vectors", "version": 1, "num_states": 2, "num_actions": 3, )";
  expect_rejected("{\n\"format\": \n  oops\n}", 3, "not valid JSON");
  expect_rejected(R"({"version": 1})", 0, "missing key \"format\"");
  expect_rejected(R"({"format": "echoplan-alpha-vectors", "version": 1, "num_states": 5,
                     "num_actions": 3, "vectors": []})",
                  0, "solve this problem again");
  expect_rejected(head + R"("vectors": []})", 0, "non-empty array");
  expect_rejected(head + R"("vectors": [{"action": 7, "values": [1, 2]}]})", 0, "vectors[0].action 7");
  expect_rejected(head + R"("vectors": [{"action": 0, "values": [1]}]})", 0, "array of 2 numbers");
  expect_rejected(head + R"("vectors": [{"action": 0, "values": [1, "x"]}]})", 0, "non-number");
}

TEST(PolicyFile, MissingFileIsAnInputError) {
  const DensePomdp m = make_dense_pomdp(testing::tiger());
  EXPECT_THROW(load_policy("/nonexistent/policy.json", m), InputError);
}

}  // namespace
}  // namespace echoplan::solvers::offline
