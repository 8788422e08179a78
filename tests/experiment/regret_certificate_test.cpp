// The regret certificate on logs whose regret follows by hand, on a real ABT run's log (through the
// shipped TrialLog, ObjectIdentificationModel and ParticleBelief), and its errors on bad logs.
#include "experiment/regret_certificate.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "../common/source_dir.h"
#include "../solvers/limited_problems.h"
#include "common/error.h"
#include "pomdp/object_identification_model.h"
#include "pomdp/problem.h"

namespace echoplan::experiment {
namespace {

namespace fs = std::filesystem;
using solvers::testing::one_noisy_sensor;

std::string repo_file(const std::string& relative) {
  return echoplan::testing::source_dir() + "/" + relative;
}

pomdp::ObjectProblemData perfect_sensing_report() {
  const pomdp::Problem p = pomdp::load_problem(repo_file("problems/audio_objects.yaml"));
  auto d = (*p.model->object_identification()).data();
  for (auto& action : d.observation_table)
    for (std::size_t k = 0; k < action.size(); ++k)
      for (std::size_t o = 0; o < action[k].size(); ++o) action[k][o] = (o == k) ? 1.0 : 0.0;
  return d;
}

fs::path write_steps(const std::string& name, const std::string& rows) {
  const fs::path path = fs::temp_directory_path() / ("echoplan_certify_" + name + ".csv");
  std::ofstream out(path);
  out << "trial,step,action,observation,p_a,p_b,p_c,p_d,reward,episodes\n" << rows;
  return path;
}

Certificate certify_file(const pomdp::ObjectIdentificationModel& model, const fs::path& steps) {
  solvers::IdentificationSolver solver(*model.tabular());
  CertifyOptions options;
  options.decision_gap = 1e-9;
  return certify_trials(solver, read_steps_csv(steps, model.spec()), options, steps.string());
}

TEST(RegretCertificate, HandComputedRegretsOnPerfectSensing) {
  // With perfect sensing V*(b0) = -1 + 0.99 * 10 = 8.9. Trial 0 plays optimally (regret 0);
  // trial 1 sorts blind (-45: regret 53.9); trial 2 senses, then sorts wrongly after hearing the
  // mug (a known mug sorted to A: V* = 10, Q = -100, discounted by 0.99: regret 108.9).
  const pomdp::ObjectIdentificationModel model(perfect_sensing_report());
  const fs::path steps = write_steps("hand",
                                     "0,0,strike,coffee_mug,0,0,0,0,-1,10\n"
                                     "0,1,move_to_B,none,0,0,0,0,10,10\n"
                                     "1,0,move_to_A,none,0,0,0,0,-100,10\n"
                                     "2,0,slide,coffee_mug,0,0,0,0,-1,10\n"
                                     "2,1,move_to_A,none,0,0,0,0,-100,10\n");
  const Certificate c = certify_file(model, steps);
  ASSERT_EQ(c.trials.size(), 3u);
  EXPECT_NEAR(c.vstar.lower, 8.9, 1e-9);
  EXPECT_NEAR(c.trials[0].regret, 0.0, 1e-9);
  EXPECT_NEAR(c.trials[1].regret, 53.9, 1e-9);
  EXPECT_NEAR(c.trials[2].regret, 0.99 * 110.0, 1e-9);
  EXPECT_NEAR(c.regret.mean, (53.9 + 108.9) / 3.0, 1e-9);
  // Three trials: the t quantile with 2 degrees of freedom, 4.303, not 1.96.
  const double sd = c.regret.sd;
  EXPECT_NEAR(c.regret.half_width, 4.302652730 * sd / std::sqrt(3.0), 1e-9);
  ASSERT_FALSE(c.worst.empty());
  EXPECT_NEAR(c.worst[0].loss, 110.0, 1e-9);
  EXPECT_EQ(c.worst[0].best_action, 3);  // move_to_B: the mug belongs at B
  // Every value here is exact, so the certificate adds no looseness of its own.
  EXPECT_NEAR(c.bound_gap_mean, 0.0, 1e-9);
  fs::remove(steps);
}

TEST(RegretCertificate, LoosenessBoundsTheDistanceBetweenTheTwoRegrets) {
  // The report's noisy problem with a search limit too small to converge: the bounds stay valid,
  // and the two regret figures (from the bounds' two ends) differ by at most the summed gaps
  // reported.
  const pomdp::Problem problem =
      pomdp::load_problem(echoplan::testing::source_dir() + "/problems/audio_objects.yaml");
  const auto& model = (*problem.model->object_identification());
  const fs::path steps = write_steps("loose",
                                     "0,0,strike,coffee_mug,0,0,0,0,-1,10\n"
                                     "0,1,strike,coffee_mug,0,0,0,0,-1,10\n"
                                     "0,2,move_to_B,none,0,0,0,0,10,10\n"
                                     "1,0,slide,plastic_cup,0,0,0,0,-1,10\n"
                                     "1,1,move_to_A,none,0,0,0,0,10,10\n");
  solvers::IdentificationSolver solver(*model.tabular());
  CertifyOptions options;
  options.decision_gap = 1e-9;
  options.expansions_per_belief = 30;
  options.root_expansions = 30;
  const Certificate c =
      certify_trials(solver, read_steps_csv(steps, model.spec()), options, steps.string());
  ASSERT_EQ(c.trials.size(), 2u);
  EXPECT_GT(c.unconverged_beliefs, 0);
  EXPECT_GT(c.bound_gap_mean, 0.0);
  double mean = 0.0;
  for (const TrialRegret& t : c.trials) {
    EXPECT_GE(t.regret, t.regret_lower);
    EXPECT_LE(t.regret - t.regret_lower, t.bound_gap + 1e-9);
    mean += t.bound_gap / 2.0;
  }
  EXPECT_NEAR(c.bound_gap_mean, mean, 1e-12);
  fs::remove(steps);
}

TEST(RegretCertificate, LooseBoundsNeverCertifyLessRegretThanTightOnes) {
  // The upper end of a loss is measured against the best rival action's upper bound on Q* (not
  // V*'s): it must stay sound. The same log on the report's noisy problem, certified with bounds
  // far from converged and with bounds near convergence: the loose certificate's regret is never
  // below the tight one's lower end, and the tight one's two ends nearly meet.
  const pomdp::Problem problem =
      pomdp::load_problem(echoplan::testing::source_dir() + "/problems/audio_objects.yaml");
  const auto& model = (*problem.model->object_identification());
  const fs::path steps = write_steps("rival",
                                     "0,0,strike,coffee_mug,0,0,0,0,-1,10\n"
                                     "0,1,strike,coffee_mug,0,0,0,0,-1,10\n"
                                     "0,2,strike,plastic_cup,0,0,0,0,-1,10\n"
                                     "0,3,move_to_B,none,0,0,0,0,10,10\n"
                                     "1,0,slide,paper_base,0,0,0,0,-1,10\n"
                                     "1,1,slide,paper_base,0,0,0,0,-1,10\n"
                                     "1,2,strike,paper_base,0,0,0,0,-1,10\n"
                                     "1,3,move_to_B,none,0,0,0,0,10,10\n");
  auto certify = [&](long expansions) {
    solvers::IdentificationSolver solver(*model.tabular());
    CertifyOptions options;
    options.decision_gap = 1e-6;
    options.expansions_per_belief = expansions;
    options.root_expansions = expansions;
    return certify_trials(solver, read_steps_csv(steps, model.spec()), options, steps.string());
  };
  const Certificate loose = certify(30), tight = certify(1500);
  ASSERT_EQ(loose.trials.size(), 2u);
  ASSERT_EQ(tight.trials.size(), 2u);
  for (std::size_t t = 0; t < 2; ++t) {
    EXPECT_GE(loose.trials[t].regret, tight.trials[t].regret_lower - 1e-9) << "trial " << t;
    EXPECT_LE(loose.trials[t].regret_lower, tight.trials[t].regret + 1e-9) << "trial " << t;
    EXPECT_LT(tight.trials[t].regret - tight.trials[t].regret_lower,
              0.25 * (loose.trials[t].regret - loose.trials[t].regret_lower) + 1e-9)
        << "trial " << t;
  }
  fs::remove(steps);
}

TEST(RegretCertificate, CutShortTrialsCountTheValueLeftBehind) {
  // One sense then the step cap: regret 0 for the sense, plus 0.99 * V*(known mug) = 0.99 * 10.
  const pomdp::ObjectIdentificationModel model(perfect_sensing_report());
  const fs::path steps = write_steps("capped", "0,0,strike,coffee_mug,0,0,0,0,-1,10\n");
  const Certificate c = certify_file(model, steps);
  ASSERT_EQ(c.trials.size(), 1u);
  EXPECT_FALSE(c.trials[0].ended);
  EXPECT_NEAR(c.trials[0].regret, 9.9, 1e-9);
  fs::remove(steps);
}

TEST(RegretCertificate, BadLogsNameTheLine) {
  const pomdp::ObjectIdentificationModel model(perfect_sensing_report());
  auto expect_error_at = [&](const std::string& rows, int line, const std::string& words) {
    const fs::path steps = write_steps("bad", rows);
    try {
      certify_file(model, steps);
      ADD_FAILURE() << "no error for " << rows;
    } catch (const InputError& e) {
      EXPECT_EQ(e.line(), line) << e.what();
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
    fs::remove(steps);
  };
  expect_error_at("0,0,jump,none,0,0,0,0,-1,10\n", 2, "unknown action 'jump'");
  expect_error_at("0,0,strike,banana,0,0,0,0,-1,10\n", 2, "unknown observation 'banana'");
  expect_error_at("0,1,strike,coffee_mug,0,0,0,0,-1,10\n", 2, "step 1 where step 0");
  expect_error_at("0,0,move_to_A,none,0,0,0,0,-1,10\n0,1,strike,coffee_mug,0,0,0,0,-1,10\n", 3,
                  "after its episode ended");
  // Perfect sensing heard the mug, then the can: no object sounds like both.
  expect_error_at(
      "0,0,strike,coffee_mug,0,0,0,0,-1,10\n0,1,strike,pringles_can,0,0,0,0,-1,10\n"
      "0,2,move_to_A,none,0,0,0,0,-1,10\n",
      3, "cannot follow");
  expect_error_at("0,0,strike\n", 2, "fields");
}

// `model`: one of limited_problems.h's.
Certificate certify_with_limits(const pomdp::Model& model, const fs::path& steps) {
  solvers::IdentificationSolver solver(
      solvers::read_identification_tables(*model.tabular(), solvers::UseLimits(model)));
  CertifyOptions options;
  options.decision_gap = 1e-9;
  return certify_trials(solver, read_steps_csv(steps, model.spec()), options, steps.string());
}

TEST(RegretCertificate, DecisionsAreJudgedWithTheUsesLeftInTheirTrial) {
  // With one listen: V*(b0) = -1 + 0.9 (0.8·10 - 0.2·100) = -11.8, reached by listening once and
  // sorting to what was heard. After the listen (the last allowed use) committing is all that is
  // left, so trial 0 loses nothing. Trial 1 sorts against what it heard: at belief 0.2 on a,
  // V* = 0.8·10 - 0.2·100 = -12 and to_a earns 0.2·10 - 0.8·100 = -78: a loss of 66, 0.9·66.
  const pomdp::ModelPtr once = one_noisy_sensor(1);
  const fs::path steps = write_steps("uses",
                                     "0,0,listen,a,0,0,0,0,-1,10\n"
                                     "0,1,to_a,none,0,0,0,0,10,10\n"
                                     "1,0,listen,b,0,0,0,0,-1,10\n"
                                     "1,1,to_a,none,0,0,0,0,-100,10\n");
  const Certificate c = certify_with_limits(*once, steps);
  ASSERT_EQ(c.trials.size(), 2u);
  EXPECT_NEAR(c.vstar.lower, -11.8, 1e-9);
  EXPECT_NEAR(c.vstar.upper, -11.8, 1e-9);
  EXPECT_NEAR(c.trials[0].regret, 0.0, 1e-9);
  EXPECT_NEAR(c.trials[1].regret, 0.9 * 66.0, 1e-9);
  // Without the limit, listening again at 0.8 beats committing (-1 + 0.9 (0.68·60/17 - 0.32·45)
  // = -11.8 > -12), so the same log would be charged for trial 0's commit.
  const Certificate unlimited = certify_with_limits(*one_noisy_sensor(0), steps);
  EXPECT_GE(unlimited.trials[0].regret, 0.9 * 0.2 - 1e-9);
  fs::remove(steps);
}

TEST(RegretCertificate, AStepPastItsUseLimitNamesTheLine) {
  const fs::path steps = write_steps("past_limit",
                                     "0,0,listen,a,0,0,0,0,-1,10\n"
                                     "0,1,listen,a,0,0,0,0,-1,10\n");
  try {
    certify_with_limits(*one_noisy_sensor(1), steps);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 3);
    EXPECT_NE(e.problem().find("use limit"), std::string::npos) << e.what();
  }
  fs::remove(steps);
}

// The share of V* falls below 100% by the regret's share of V*'s size, whatever V*'s sign: a task
// whose best policy loses 10 and an arm that loses 11 reach 90%, not 110%.
TEST(RegretCertificate, TheShareOfVStarIsBelowOneForARegretWhateverTheSignOfVStar) {
  EXPECT_DOUBLE_EQ(share_of_vstar({9.0, 11.0}, 1.0), 0.9);
  EXPECT_DOUBLE_EQ(share_of_vstar({-11.0, -9.0}, 1.0), 0.9);
  EXPECT_DOUBLE_EQ(share_of_vstar({-10.0, -10.0}, 0.0), 1.0);
  EXPECT_DOUBLE_EQ(share_of_vstar({0.0, 0.0}, 1.0), 0.0);
}

}  // namespace
}  // namespace echoplan::experiment
