// The solver's alpha vectors used as a policy through the Solver interface: the value it really
// earns, and its file round trip.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "../../common/source_dir.h"
#include "common/error.h"
#include "common/rng.h"
#include "pomdp/exact_belief.h"
#include "pomdp/problem.h"
#include "solvers/offline/offline_policy_solver.h"
#include "solvers/offline/point_based_solver.h"
#include "solvers/offline/policy_file.h"
#include "test_problems.h"

namespace echoplan::solvers::offline {
namespace {

class SolvedReportProblem : public ::testing::Test {
 protected:
  void SetUp() override {
    problem =
        pomdp::load_problem(echoplan::testing::source_dir() + "/problems/audio_objects.pomdp");
    dense = std::make_shared<const FlatPomdp>(make_flat_pomdp(*problem.model->tabular()));
    SolverOptions options;
    options.max_trials = 300;  // a fixed amount of work: the same vectors on every machine
    solver = std::make_unique<PointBasedSolver>(dense, options);
    result = solver->solve();
  }
  OfflinePolicySolver policy() const {
    return OfflinePolicySolver(problem.model, dense, solver->lower_bound());
  }
  pomdp::Problem problem;
  std::shared_ptr<const FlatPomdp> dense;
  std::unique_ptr<PointBasedSolver> solver;
  SolverProgress result;
};

// Running the policy through the Solver interface against the model itself must earn its lower
// bound (and cannot beat V*): the mean over many episodes lies within 4 standard errors of
// [lower, upper].
TEST_F(SolvedReportProblem, PolicyEarnsItsLowerBoundInSimulation) {
  OfflinePolicySolver agent = policy();
  const pomdp::ExactBelief b0(problem.model);
  Rng rng(derive_seed(2024, {3}));
  const int episodes = 20000;
  const double discount = problem.model->spec().discount;
  double sum = 0.0, sum_sq = 0.0;
  for (int e = 0; e < episodes; ++e) {
    agent.reset(b0, rng);
    pomdp::State state = problem.model->sample_initial_state(rng);
    double total = 0.0, weight = 1.0;
    for (int step = 0; step < 1000; ++step) {
      agent.improve(Budget::episodes(1), rng);
      const int a = agent.best_action();
      const pomdp::StepResult r = problem.model->step(state, a, rng);
      total += weight * r.reward;
      weight *= discount;
      if (r.terminal) break;
      agent.update(a, r.observation, b0, rng);
      state = r.next;
    }
    sum += total;
    sum_sq += total * total;
  }
  const double mean = sum / episodes;
  const double stderr_mean = std::sqrt((sum_sq / episodes - mean * mean) / episodes);
  EXPECT_GE(mean, result.root.lower - 4 * stderr_mean);
  EXPECT_LE(mean, result.root.upper + 4 * stderr_mean);
}

TEST_F(SolvedReportProblem, FirstActionIsStrikeAndBeliefFollowsObservations) {
  OfflinePolicySolver agent = policy();
  Rng rng(1);
  agent.reset(pomdp::ExactBelief(problem.model), rng);
  EXPECT_EQ(agent.best_action(), testing::kStrike);
  EXPECT_NEAR(agent.value(), result.root.lower, 1e-12);
  // The one-step lookahead value of the strike is at least the lower bound (a backup never loses).
  EXPECT_GE(agent.root_action_values()[testing::kStrike], result.root.lower - 1e-9);
  // Strike heard as object 3: P(o=3 | s) = (0.05, 0.05, 0.11, 0.67) normalised.
  pomdp::Observation heard;
  heard.index = 3;
  agent.update(testing::kStrike, heard, pomdp::ExactBelief(problem.model), rng);
  EXPECT_NEAR(agent.belief()[3], 0.67 / (0.05 + 0.05 + 0.11 + 0.67), 1e-12);
}

TEST_F(SolvedReportProblem, PolicyFileRoundTrip) {
  const auto path = std::filesystem::temp_directory_path() / "echoplan_offline_policy_test.json";
  save_policy(*solver, path.string());
  const AlphaVectorSet loaded = load_policy(path.string(), solver->pomdp());
  ASSERT_EQ(loaded.size(), solver->lower_bound().size());
  const BeliefVector b0 = solver->pomdp().initial_belief;
  EXPECT_DOUBLE_EQ(loaded.value(b0), solver->lower_bound().value(b0));
  EXPECT_EQ(loaded.best_action(b0), testing::kStrike);
  // The same file drives the trials runner's solver.
  SolverOptions unused;
  auto agent = make_offline_solver(problem.model, unused, path.string());
  Rng rng(1);
  agent->reset(pomdp::ExactBelief(problem.model), rng);
  EXPECT_EQ(agent->best_action(), testing::kStrike);
  std::filesystem::remove(path);
}

// Writes `text` to a temporary file and expects load_policy to reject it with `line` and a message
// containing `fragment`.
void expect_rejected(const std::string& text, int line, const std::string& fragment) {
  const auto path = std::filesystem::temp_directory_path() / "echoplan_offline_bad_policy.json";
  std::ofstream(path) << text;
  const FlatPomdp m = make_flat_pomdp(testing::tiger());
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
      R"({"format": "echoplan-alpha-vectors", "version": 1, "num_states": 2, "num_actions": 3,
          "discount": 0.95, )";
  expect_rejected("{\n\"format\": \n  oops\n}", 3, "not valid JSON");
  expect_rejected(R"({"version": 1})", 0, "missing key \"format\"");
  expect_rejected(R"({"format": "echoplan-alpha-vectors", "version": 1, "num_states": 5,
                     "num_actions": 3, "vectors": []})",
                  0, "solve this problem again");
  expect_rejected(head + R"("vectors": []})", 0, "non-empty array");
  expect_rejected(head + R"("vectors": [{"action": 7, "values": [1, 2]}]})", 0,
                  "vectors[0].action 7");
  expect_rejected(head + R"("vectors": [{"action": 0, "values": [1]}]})", 0, "array of 2 numbers");
  expect_rejected(head + R"("vectors": [{"action": 0, "values": [1, "x"]}]})", 0, "non-number");
}

TEST(PolicyFile, MissingFileIsAnInputError) {
  const FlatPomdp m = make_flat_pomdp(testing::tiger());
  EXPECT_THROW(load_policy("/nonexistent/policy.json", m), InputError);
}

}  // namespace
}  // namespace echoplan::solvers::offline

namespace echoplan::solvers::offline {
namespace {

// A generative-only model (no tables), as a continuous-observation problem would be.
class GenerativeOnlyModel : public pomdp::Model {
 public:
  const pomdp::ModelSpec& spec() const override { return spec_; }
  pomdp::State sample_initial_state(Rng&) const override { return {}; }
  pomdp::StepResult step(const pomdp::State& s, int, Rng&) const override { return {s, {}, 0.0}; }
  double observation_likelihood(const pomdp::State&, int,
                                const pomdp::Observation&) const override {
    return 1.0;
  }

 private:
  pomdp::ModelSpec spec_;
};

TEST(MakeOfflineSolver, ModelWithoutTablesIsAnInputError) {
  try {
    make_offline_solver(std::make_shared<GenerativeOnlyModel>(), SolverOptions{}, "", "robot.yaml");
    ADD_FAILURE() << "accepted a model without tables";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "robot.yaml");
    EXPECT_NE(e.problem().find("needs a problem with tables"), std::string::npos);
  }
}

}  // namespace
}  // namespace echoplan::solvers::offline
