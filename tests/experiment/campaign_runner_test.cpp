// The campaign runner's parts that need no world: an arm's planner (the campaign's solver and
// budget, the arm problem's search settings) and the numbering of the trials.
#include "experiment/campaign_runner.h"

#include <gtest/gtest.h>

#include <array>

#include "../common/source_dir.h"
#include "experiment/campaign_arms.h"

namespace echoplan::experiment {
namespace {

// audio_objects.yaml asks for depth 100, exploration 110 and 1000 particles (its planner section).
const std::string kProblem = echoplan::testing::source_dir() + "/problems/audio_objects.yaml";

TEST(CampaignRunner, AnArmPlansWithTheCampaignsSolverAndBudgetAndTheProblemsSearch) {
  CampaignConfig config;
  config.planner.solver = "pomcp";
  config.planner.episodes = 120;
  const pomdp::Problem problem = pomdp::load_problem(kProblem);
  config.arms = {CampaignArm{}};
  const loop::Planner p = loop::make_planner(resolve_arms(config)[0].planner, problem, kProblem);
  EXPECT_EQ(p.name, "pomcp");
  EXPECT_EQ(p.budget.kind, solvers::Budget::Kind::episodes);
  EXPECT_EQ(p.budget.amount, 120);
  EXPECT_EQ(p.options.max_depth, 100);
  EXPECT_EQ(p.options.exploration, 110.0);
  EXPECT_EQ(p.options.root_particles, 1000);

  config.planner.episodes = 0;
  config.planner.step_ms = 40;
  const loop::Planner timed =
      loop::make_planner(resolve_arms(config)[0].planner, problem, kProblem);
  EXPECT_EQ(timed.budget.kind, solvers::Budget::Kind::milliseconds);
  EXPECT_EQ(timed.budget.amount, 40);
}

TEST(CampaignRunner, AStrategyArmDecidesByItsStrategyNotTheCampaignsSolver) {
  CampaignConfig config;
  config.planner.solver = "abt";
  config.planner.episodes = 120;
  config.arms.resize(2);
  config.arms[0].strategy = "best_single";
  config.arms[1].strategy = kPlanStrategy;
  const std::vector<ResolvedArm> arms = resolve_arms(config);
  EXPECT_EQ(arms[0].planner.solver, "best_single");
  EXPECT_EQ(arms[1].planner.solver, "abt");
}

TEST(CampaignRunner, JobsNumberArmsThenGroupsThenTrials) {
  std::vector<ObjectGroup> groups(2);
  groups[0].trials = 2;
  groups[1].trials = 1;
  const std::vector<TrialJob> jobs = campaign_jobs(2, groups);
  // (arm, group, index) in id order.
  const std::vector<std::array<int, 3>> expected = {{0, 0, 0}, {0, 0, 1}, {0, 1, 0},
                                                    {1, 0, 0}, {1, 0, 1}, {1, 1, 0}};
  ASSERT_EQ(jobs.size(), expected.size());
  for (std::size_t i = 0; i < jobs.size(); ++i) {
    EXPECT_EQ(jobs[i].id, static_cast<int>(i));
    EXPECT_EQ((std::array<int, 3>{jobs[i].arm, jobs[i].group, jobs[i].index}), expected[i]) << i;
  }
}

}  // namespace
}  // namespace echoplan::experiment
