// Trials end to end on the report's shipped problem (problems/audio_objects.yaml, its
// ObjectIdentificationModel as the world, ParticleBelief as the belief): files, determinism,
// stopping, and ABT's decisions certified against the exact V* (regret_certificate.h).
#include "loop/trial_runner.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <memory>
#include <sstream>
#include <string>

#include "../common/source_dir.h"
#include "common/error.h"
#include "experiment/regret_certificate.h"
#include "experiment/trial_log.h"
#include "experiment/trial_records.h"
#include "experiment/trial_summary.h"
#include "loop/table_world.h"
#include "pomdp/particle_belief.h"
#include "pomdp/problem.h"
#include "solvers/abt_solver.h"
#include "solvers/planner_overrides.h"

namespace echoplan::experiment {
namespace {

std::string slurp(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

int count_lines(const std::string& text) {
  return static_cast<int>(std::count(text.begin(), text.end(), '\n'));
}

pomdp::Problem report_problem() {
  return pomdp::load_problem(echoplan::testing::source_dir() + "/problems/audio_objects.yaml");
}

struct Harness {
  Harness() = default;
  // With the given --leaf (the problem's defaults otherwise).
  explicit Harness(const std::string& leaf) {
    solvers::PlannerOverrides overrides;
    overrides.leaf = leaf;
    solver =
        std::make_unique<solvers::AbtSolver>(model, solvers::search_options(overrides, problem));
  }
  pomdp::Problem problem = report_problem();
  pomdp::ModelPtr model = problem.model;
  loop::TableWorld world{model};
  std::unique_ptr<solvers::AbtSolver> solver =
      std::make_unique<solvers::AbtSolver>(model, solvers::search_options({}, problem));
  loop::TrialParts setup() {
    loop::TrialParts s;
    s.model = model.get();
    s.world = &world;
    s.solver = solver.get();
    s.make_belief = [m = model, n = problem.belief.particles](Rng& rng) {
      return std::make_unique<pomdp::ParticleBelief>(m, n, rng);
    };
    return s;
  }
};

using loop::TrialOptions;
using TrialObserver = std::function<void(const TrialRecord&, const std::vector<StepRecord>&)>;

// For tests that only look at run_trials()'s return value.
const TrialObserver Ignore = [](const TrialRecord&, const std::vector<StepRecord>&) {};

// The trials `echoplan trials` runs: options.total_trials() of them, per object or drawn, each
// reported to `observer`, until `stop`.
std::vector<TrialRecord> run_trials(const loop::TrialParts& parts, const TrialOptions& options,
                                    const TrialObserver& observer,
                                    const std::atomic<bool>* stop = nullptr) {
  options.validate();
  std::vector<TrialRecord> finished;
  for (int t = 0; t < options.total_trials(parts.model->spec()); ++t) {
    const auto trial = loop::run_trial(parts, options, t, options.object_of_trial(t), {}, stop);
    if (!trial) break;
    const TrialResult result = records_of(*trial);
    observer(result.record, result.steps);
    finished.push_back(result.record);
  }
  return finished;
}

std::filesystem::path fresh_dir(const std::string& name) {
  auto dir = std::filesystem::temp_directory_path() / ("echoplan_trials_" + name);
  std::filesystem::remove_all(dir);
  return dir;
}

// Runs trials into `dir` and writes the summary, as `echoplan trials` does.
std::vector<TrialRecord> run_into(const std::filesystem::path& dir, const TrialOptions& options,
                                  const std::atomic<bool>* stop = nullptr) {
  Harness h;
  TrialLog log(dir, h.model->spec(), 1000);
  auto trials = run_trials(
      h.setup(), options,
      [&](const TrialRecord& t, const std::vector<StepRecord>& s) { log.trial_finished(t, s); },
      stop);
  log.write_summary(summarize(trials, h.model->num_actions()), {{"seed", options.seed}});
  return trials;
}

TEST(Trials, SameSeedGivesByteIdenticalFiles) {
  TrialOptions options;
  options.trials = 6;
  options.budget = solvers::Budget::episodes(300);
  options.seed = 9;
  const auto a = fresh_dir("same_a"), b = fresh_dir("same_b"), c = fresh_dir("same_c");
  run_into(a, options);
  run_into(b, options);
  options.seed = 10;
  run_into(c, options);
  for (const char* file : {"trials.csv", "steps.csv", "summary.json"}) {
    EXPECT_EQ(slurp(a / file), slurp(b / file)) << file;
    EXPECT_FALSE(slurp(a / file).empty()) << file;
  }
  EXPECT_NE(slurp(a / "steps.csv"), slurp(c / "steps.csv"));
}

TEST(Trials, FilesHoldOneRowPerTrialAndPerStep) {
  TrialOptions options;
  options.trials = 5;
  options.budget = solvers::Budget::episodes(200);
  const auto dir = fresh_dir("rows");
  const auto trials = run_into(dir, options);
  int steps = 0;
  for (const auto& t : trials) steps += t.steps;
  const std::string trials_csv = slurp(dir / "trials.csv");
  EXPECT_EQ(count_lines(trials_csv), 1 + 5);
  EXPECT_EQ(trials_csv.substr(0, trials_csv.find('\n')),
            "trial,true_state,believed_state,steps,n_slide,n_strike,n_move_to_A,n_move_to_B,"
            "discounted_reward,collision");
  const std::string steps_csv = slurp(dir / "steps.csv");
  EXPECT_EQ(count_lines(steps_csv), 1 + steps);
  // The first step of every trial is planned from the uniform initial belief: particle counts
  // near 250 each (1000 particles; 4 binomial standard deviations is about 55).
  std::istringstream lines(steps_csv);
  std::string header, first;
  std::getline(lines, header);
  std::getline(lines, first);
  EXPECT_EQ(header,
            "trial,step,action,observation,particles_pringles_can,particles_coffee_mug,"
            "particles_plastic_cup,particles_paper_base,reward,episodes,heard_probability,"
            "heard_ebr_db");
  std::vector<std::string> fields;
  std::stringstream row(first);
  for (std::string f; std::getline(row, f, ',');) fields.push_back(f);
  ASSERT_EQ(fields.size(), 11u);  // getline drops the last (empty) field
  int total = 0;
  for (int k = 4; k < 8; ++k) {
    EXPECT_NEAR(std::stoi(fields[k]), 250, 55);
    total += std::stoi(fields[k]);
  }
  EXPECT_EQ(total, 1000);
  EXPECT_EQ(fields[9], "200");
}

TEST(Trials, PerObjectRunsKTrialsForEachObject) {
  Harness h;
  TrialOptions options;
  options.trials = 0;
  options.per_object = 3;
  options.budget = solvers::Budget::episodes(100);
  const auto trials = run_trials(h.setup(), options, Ignore);
  ASSERT_EQ(trials.size(), 12u);
  for (int t = 0; t < 12; ++t) EXPECT_EQ(trials[t].true_state, t / 3);
}

TEST(Trials, MaxStepsCapsATrial) {
  Harness h;
  TrialOptions options;
  options.trials = 3;
  options.max_steps = 1;
  options.budget = solvers::Budget::episodes(500);
  for (const auto& t : run_trials(h.setup(), options, Ignore)) {
    EXPECT_EQ(t.steps, 1);
    EXPECT_TRUE(t.capped);  // from the uniform belief no planner sorts at once
  }
}

TEST(Trials, StopRequestKeepsFinishedTrialsAndValidFiles) {
  // Stops after the second trial finishes, as Ctrl-C would between trials.
  Harness h;
  std::atomic<bool> stop{false};
  const auto dir = fresh_dir("stop");
  TrialLog log(dir, h.model->spec(), 1000);
  int seen = 0;
  const TrialObserver stop_after_two = [&](const TrialRecord& t, const std::vector<StepRecord>& s) {
    log.trial_finished(t, s);
    if (++seen == 2) stop = true;
  };
  TrialOptions options;
  options.trials = 10;
  options.budget = solvers::Budget::episodes(100);
  EXPECT_EQ(run_trials(h.setup(), options, stop_after_two, &stop).size(), 2u);
  EXPECT_EQ(count_lines(slurp(dir / "trials.csv")), 1 + 2);
}

// A solver that strikes whatever it is told: on a problem where strike may be used once, the
// second strike must stop the trial with a clear logic error (it would ask the world for a
// performance it does not have).
class AlwaysStrike final : public solvers::Solver {
 public:
  void reset(const pomdp::Belief&, Rng&) override {}
  void improve(const solvers::Budget&, Rng&) override {}
  int best_action() const override { return 1; }  // strike
  std::vector<double> root_action_values() const override { return {}; }
  void update(int, const pomdp::Observation&, const pomdp::Belief&, Rng&) override {}
  solvers::SolverStats stats() const override { return {}; }
};

TEST(Trials, ASolverChoosingAUsedUpActionIsALogicError) {
  pomdp::ObjectProblemData d = report_problem().model->object_identification()->data();
  d.sensing[1].uses = 1;
  const auto model = std::make_shared<const pomdp::ObjectIdentificationModel>(std::move(d));
  loop::TableWorld world{model};
  AlwaysStrike solver;
  loop::TrialParts parts;
  parts.model = model.get();
  parts.world = &world;
  parts.solver = &solver;
  parts.make_belief = [model](Rng& rng) {
    return std::make_unique<pomdp::ParticleBelief>(model, 100, rng);
  };
  try {
    loop::run_trial(parts, TrialOptions{}, 0, -1, {});
    FAIL() << "no error";
  } catch (const std::logic_error& e) {
    EXPECT_NE(std::string(e.what()).find("'strike'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("1 allowed use"), std::string::npos) << e.what();
  }
}

TEST(Trials, BadOptionsAreInputErrors) {
  Harness h;
  TrialOptions options;
  options.max_steps = 0;
  EXPECT_THROW(run_trials(h.setup(), options, Ignore), InputError);
  options = {};
  options.per_object = -1;
  EXPECT_THROW(run_trials(h.setup(), options, Ignore), InputError);
  options = {};
  options.budget = solvers::Budget::milliseconds(0);
  EXPECT_THROW(run_trials(h.setup(), options, Ignore), InputError);
  EXPECT_THROW(TrialLog("/proc/no_such_dir/out", h.model->spec(), 0), InputError);
}

// 12 trials of ABT with `leaf` at 1000 episodes per step on the report's problem (seed 2026),
// logged and certified within a test's budget: 100,000 exact-solver expansions at b0, then 2,000
// per visited belief (counts, so they repeat). Prints the figures under `label`.
Certificate certified_abt_trials(const std::string& leaf, const std::string& label) {
  Harness h(leaf);
  const auto dir = fresh_dir("certify_" + leaf);
  TrialOptions options;
  options.trials = 12;
  options.budget = solvers::Budget::episodes(1000);
  options.seed = 2026;
  {
    TrialLog log(dir, h.model->spec(), 1000);
    run_trials(h.setup(), options, [&](const TrialRecord& t, const std::vector<StepRecord>& s) {
      log.trial_finished(t, s);
    });
  }
  const std::string steps = (dir / "steps.csv").string();
  solvers::IdentificationSolver exact(*h.model->tabular());
  CertifyOptions certify;
  certify.root_expansions = 100000;
  certify.expansions_per_belief = 2000;
  const Certificate c =
      certify_trials(exact, read_steps_csv(steps, h.model->spec()), certify, steps);
  std::printf(
      "%s, %d trials of 1000 episodes/step: V* in [%.4f, %.4f], regret %.4f +- %.4f (95%% CI; "
      "lower end %.4f), certified %.1f%% of V*\n",
      label.c_str(), options.trials, c.vstar.lower, c.vstar.upper, c.regret.mean,
      c.regret.half_width, c.regret_lower_mean, 100 * c.share_of_vstar());
  return c;
}

TEST(Trials, AbtIsCertifiedToKeepFourFifthsOfTheOptimalValueOnTheReportsProblem) {
  // Every decision of every trial is scored by its exact loss V*(b_t) - Q*(b_t, a_t) at the exact
  // belief of its history (regret_certificate.h); the discounted sum per trial has expectation
  // V*(b0) - V^ABT(b0) with a fraction of the returns' variance. The bounds come from the exact
  // solver within a test's budget (100,000 expansions at b0, then 2,000 per visited belief: counts,
  // so they repeat), and the regret asserted is the upper end (U_V - L_Q): the certificate can only
  // err against the planner. ABT with the policy leaf (its default before the exact leaf, and its
  // fallback where the exact solver has no node) and 1000 episodes per step must keep a certified
  // 80% of V*(b0) = 2.9534: mean regret plus its 95% CI half-width <= 0.2 V* (measured: 0.076 +-
  // 0.069; lower end 0.035).
  // That rejects the lookahead leaf ABT had before (its certificate: docs/BENCHMARKS.md, "Certified
  // share of V*") and the fixed rule "strike until 98% sure" (2.452, regret 0.50), as well as every
  // planner that sorts on thin evidence (value below 0).
  const Certificate c = certified_abt_trials("policy", "ABT, policy leaf");
  ASSERT_EQ(c.trials.size(), 12u);
  // The bounds on V*(b0) contain the value DESIGN.md gives (exact search to 1e-4).
  EXPECT_LE(c.vstar.lower, 2.9534);
  EXPECT_GE(c.vstar.upper, 2.9534);
  EXPECT_LT(c.vstar.upper - c.vstar.lower, 0.2);
  EXPECT_LE(c.regret.mean + c.regret.half_width, 0.2 * c.vstar.lower);
  for (const TrialRegret& t : c.trials) EXPECT_TRUE(t.ended) << "trial " << t.trial;
}

TEST(Trials, AbtWithTheExactLeafIsCertifiedWithinTwoPercentOfTheOptimalValue) {
  // The same certificate as above for ABT with the exact leaf (the exact solver refined at each
  // belief within the step's budget, 1,000 expansions here, deciding on its lower bounds): the
  // same 12 trials must keep a certified 98% of V*. Measured: regret 0.0017 +- 0.0038 (0.2% of
  // V*), lower end 0.0002; the policy leaf on these trials: 0.076 +- 0.069 (4.9%), which this
  // bound rejects. With 100 trials and certify's full budget: BENCHMARKS.md, "Certified share of
  // V*".
  const Certificate c = certified_abt_trials("exact", "ABT, exact leaf");
  ASSERT_EQ(c.trials.size(), 12u);
  EXPECT_LE(c.regret.mean + c.regret.half_width, 0.02 * c.vstar.lower);
  for (const TrialRegret& t : c.trials) EXPECT_TRUE(t.ended) << "trial " << t.trial;
}

}  // namespace
}  // namespace echoplan::experiment
