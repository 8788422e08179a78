// The closed loop end to end: the trial runner plans on a calibrated problem, and the world answers
// with the simulated robot (or replayed recordings) and the trained classifier.
#include "experiment/robot_environment.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "../common/input_error_message.h"
#include "../robot/small_training_set.h"
#include "audio/io.h"
#include "common/error.h"
#include "experiment/calibrated_problem.h"
#include "experiment/environment_factory.h"
#include "experiment/trial_records.h"
#include "pomdp/make_belief.h"
#include "pomdp/problem.h"
#include "robot/classifier_service.h"
#include "robot/replay_recorder.h"
#include "solvers/make_solver.h"

namespace echoplan::experiment {
namespace {

namespace fs = std::filesystem;

const std::vector<std::string> kObjects{"coffee_mug", "plastic_cup"};

std::shared_ptr<const perception::ObservationModel> model() {
  static const auto m = testing::train_small_model(kObjects, {"slide", "strike"}, 3);
  return m;
}

// Mug or cup, sorted to A (mug) or B (cup); the seed report's rewards. Observation symbols and
// table: `symbols` with a uniform table (calibrated_problem replaces both).
pomdp::ObjectProblemData mug_or_cup(std::vector<std::string> objects = kObjects) {
  pomdp::ObjectProblemData d;
  d.name = "mug_or_cup";
  d.discount = 0.99;
  d.objects = objects;
  d.prior.assign(objects.size(), 1.0 / static_cast<double>(objects.size()));
  d.initial_joints = {-2.89527, 1.45058, -0.18396, 2.07696, -0.310356, 0.630897, -1.54233};
  d.initial_offset = {0.1, 0, 0};
  d.sensing = {{"slide", -1.0, {0.05, 0, 0}, 0.0}, {"strike", -1.0, {0, 0, 0}, 0.0}};
  d.sorting = {"move_to_A", "move_to_B"};
  d.observation_symbols = objects;
  const std::vector<double> uniform(objects.size(), 1.0 / static_cast<double>(objects.size()));
  d.observation_table.assign(2, std::vector<std::vector<double>>(objects.size(), uniform));
  d.sorting_reward = {std::vector<double>(objects.size(), -100.0),
                      std::vector<double>(objects.size(), -100.0)};
  d.sorting_reward[0][0] = 10;
  for (std::size_t k = 1; k < objects.size(); ++k) d.sorting_reward[1][k] = 10;
  return d;
}

pomdp::Problem calibrated(const pomdp::ObjectProblemData& base) {
  pomdp::Problem p;
  p.model = std::make_shared<pomdp::ObjectIdentificationModel>(calibrated_problem(base, *model()));
  p.belief.particles = 300;
  return p;
}

LoopSettings simulator_settings(pomdp::ModelPtr problem) {
  LoopSettings s;
  s.model = std::move(problem);
  s.world.kind = WorldSettings::Kind::simulator;
  s.world.catalogue = testing::shipped_catalogue();
  s.classifier = model();
  return s;
}

// Runs one trial per object through `environment`, collecting what the environment reported.
struct LoopRun {
  std::vector<TrialRecord> trials;
  std::vector<std::vector<StepRecord>> steps;
  std::vector<std::vector<LoopStep>> loop_steps;
  std::vector<std::string> world_objects;
};

class Collect final : public TrialObserver {
 public:
  explicit Collect(LoopRun& run) : run_(run) {}
  void trial_finished(const TrialRecord& t, const std::vector<StepRecord>& steps) override {
    run_.trials.push_back(t);
    run_.steps.push_back(steps);
  }

 private:
  LoopRun& run_;
};

LoopRun run_each_object(const pomdp::Problem& problem, RobotEnvironment& environment,
                        int max_steps = 30) {
  LoopRun run;
  environment.set_step_listener([&](const LoopStep& s) {
    if (s.step == 0) {
      run.loop_steps.emplace_back();
      run.world_objects.push_back(environment.world_object());
    }
    run.loop_steps.back().push_back(s);
  });
  solvers::SearchOptions search;
  search.exploration = 110;
  search.root_particles = problem.belief.particles;
  auto solver = solvers::make_solver("abt", problem.model, search);
  TrialSetup setup;
  setup.model = problem.model.get();
  setup.environment = &environment;
  setup.solver = solver.get();
  setup.make_belief = [&problem](Rng& rng) { return pomdp::make_belief(problem, rng); };
  TrialOptions options;
  options.per_object = 1;
  options.budget = solvers::Budget::episodes(300);
  options.max_steps = max_steps;
  options.seed = 3;
  Collect collect(run);
  run.trials = {};
  run_trials(setup, options, collect);
  return run;
}

// The trial's records and what the environment reported agree step by step, and the trial ended
// by sorting.
void expect_consistent_trial(const pomdp::ObjectIdentificationModel& m, const TrialRecord& trial,
                             const std::vector<StepRecord>& steps,
                             const std::vector<LoopStep>& loop) {
  ASSERT_EQ(static_cast<int>(steps.size()), trial.steps);
  ASSERT_EQ(loop.size(), steps.size());
  EXPECT_FALSE(trial.capped);
  EXPECT_FALSE(trial.collision);
  double discounted = 0, weight = 1;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const LoopStep& l = loop[i];
    const StepRecord& s = steps[i];
    EXPECT_EQ(l.step, static_cast<int>(i));
    EXPECT_EQ(l.action, s.action);
    EXPECT_EQ(l.action_name, m.spec().action_names[s.action]);
    EXPECT_EQ(l.report.action, l.action_name);
    EXPECT_EQ(l.report.status, robot::ActionStatus::done);
    EXPECT_EQ(l.observation, s.observation);
    EXPECT_EQ(l.observation_name, m.spec().observation.names[s.observation.index]);
    EXPECT_EQ(l.reward, s.reward);
    const bool last = i + 1 == loop.size();
    EXPECT_EQ(l.terminal, last);
    if (m.is_sensing(l.action)) {
      EXPECT_FALSE(last) << "a sensing action ended the trial";
      EXPECT_TRUE(l.recorded);
      EXPECT_TRUE(l.classified);
      EXPECT_GT(l.clip.frames(), 0u);
      EXPECT_EQ(l.observation_name, l.heard.unknown ? "unknown" : l.heard.label);
      EXPECT_EQ(l.reward, -1.0);
      EXPECT_FALSE(l.heard.features.empty());
      EXPECT_GE(l.observe_ms, 0.0);
    } else {
      EXPECT_TRUE(last) << "the trial went on after a sorting action";
      EXPECT_FALSE(l.recorded);
      EXPECT_EQ(l.observation.index, m.none_symbol());
      const int j = l.action - m.num_sensing();
      EXPECT_EQ(l.reward, m.data().sorting_reward[j][trial.true_state]);
    }
    discounted += weight * l.reward;
    weight *= m.spec().discount;
  }
  EXPECT_FALSE(m.is_sensing(loop.back().action));
  EXPECT_NEAR(trial.discounted_reward, discounted, 1e-9);
}

TEST(RobotEnvironment, FullTrialsWithTheSimulatedRobotEndInSortingWithAConsistentLog) {
  const pomdp::Problem problem = calibrated(mug_or_cup());
  const auto factory = make_environment_factory(simulator_settings(problem.model));
  auto environment = factory();
  const LoopRun run = run_each_object(problem, *environment);
  ASSERT_EQ(run.trials.size(), 2u);
  const auto& m = environment->model();
  for (std::size_t t = 0; t < run.trials.size(); ++t) {
    SCOPED_TRACE("trial " + std::to_string(t));
    EXPECT_EQ(run.world_objects[t], kObjects[run.trials[t].true_state]);
    expect_consistent_trial(m, run.trials[t], run.steps[t], run.loop_steps[t]);
  }
  // The planner listened before it sorted.
  EXPECT_GT(run.trials[0].steps + run.trials[1].steps, 2);
}

TEST(RobotEnvironment, ReplayedRecordingsDriveTheLoop) {
  const fs::path dir = testing::unique_temp_dir("replay_loop");
  testing::write_small_dataset(dir, kObjects, {"slide", "strike"}, 2, 77);
  const pomdp::Problem problem = calibrated(mug_or_cup());
  LoopSettings settings = simulator_settings(problem.model);
  settings.world.kind = WorldSettings::Kind::replay;
  settings.world.recordings = dir.string();
  auto environment = make_environment_factory(settings)();
  const LoopRun run = run_each_object(problem, *environment);
  ASSERT_EQ(run.trials.size(), 2u);
  for (std::size_t t = 0; t < run.trials.size(); ++t) {
    SCOPED_TRACE("trial " + std::to_string(t));
    expect_consistent_trial(environment->model(), run.trials[t], run.steps[t], run.loop_steps[t]);
    // Every clip heard is one of the true object's recordings of that action.
    const std::string object = kObjects[run.trials[t].true_state];
    for (const LoopStep& l : run.loop_steps[t]) {
      if (!l.recorded) continue;
      bool found = false;
      for (const auto& file : fs::directory_iterator(dir / object / l.action_name))
        found = found || audio::read_audio(file.path().string()).samples == l.clip.samples;
      EXPECT_TRUE(found) << l.action_name << " in trial of " << object;
    }
  }
  fs::remove_all(dir);
}

TEST(RobotEnvironment, AWeightedVariantStandsInForItsObject) {
  const pomdp::Problem problem = calibrated(mug_or_cup());
  LoopSettings settings = simulator_settings(problem.model);
  settings.world_objects = {{"coffee_mug", "coffee_mug_weighted"}};
  auto environment = make_environment_factory(settings)();
  Rng rng(1);
  environment->reset(problem.model->sample_initial_state(rng), rng);
  pomdp::State mug = problem.model->sample_initial_state(rng);
  mug.discrete[0] = 0;
  environment->reset(mug, rng);
  EXPECT_EQ(environment->world_object(), "coffee_mug_weighted");
  mug.discrete[0] = 1;
  environment->reset(mug, rng);
  EXPECT_EQ(environment->world_object(), "plastic_cup");
}

TEST(RobotEnvironment, ASlideMovesTheTrueStateAsTheModelSays) {
  const pomdp::Problem problem = calibrated(mug_or_cup());
  auto environment = make_environment_factory(simulator_settings(problem.model))();
  Rng rng(2);
  const pomdp::State start = problem.model->sample_initial_state(rng);
  environment->reset(start, rng);
  environment->execute(0, rng);  // slide: +5 cm along x
  EXPECT_NEAR(environment->true_state().continuous[pomdp::ObjectIdentificationModel::kOffsetX],
              start.continuous[pomdp::ObjectIdentificationModel::kOffsetX] + 0.05, 1e-12);
  EXPECT_EQ(environment->true_state().discrete, start.discrete);
}

// A robot whose strike always hits the table: the environment must turn that into the model's
// collision (observation `none`, the collision flag, the collision reward, the end of the trial).
class CollidingRobot final : public robot::Robot {
 public:
  void begin_trial(const robot::TrialContext&) override {}
  robot::ActionReport execute(const std::string& action) override {
    if (action == "strike")
      return {action, robot::ActionStatus::collision, "the arm touched the table", 0.4};
    return {action, robot::ActionStatus::done, "", 0.1};
  }
};

TEST(RobotEnvironment, ACollisionIsHeardAsNothingAndEndsTheTrial) {
  const fs::path dir = testing::unique_temp_dir("collision");
  testing::write_small_dataset(dir, kObjects, {"slide", "strike"}, 1, 5);
  const pomdp::Problem problem = calibrated(mug_or_cup());
  RobotParts parts;
  parts.robot = std::make_unique<CollidingRobot>();
  parts.recorder = std::make_unique<robot::ReplayRecorder>(dir);
  parts.service = std::make_unique<robot::ClassifierService>(model());
  RobotEnvironment environment(problem.model, std::move(parts));
  LoopStep seen;
  environment.set_step_listener([&](const LoopStep& s) { seen = s; });
  Rng rng(4);
  environment.reset(problem.model->sample_initial_state(rng), rng);
  const pomdp::Outcome slide = environment.execute(0, rng);
  EXPECT_FALSE(slide.collision);
  EXPECT_FALSE(slide.terminal);
  const pomdp::Outcome strike = environment.execute(1, rng);
  const auto& m = environment.model();
  EXPECT_TRUE(strike.collision);
  EXPECT_TRUE(strike.terminal);
  EXPECT_EQ(strike.observation.index, m.none_symbol());
  EXPECT_EQ(strike.reward, m.data().collision_reward);
  EXPECT_EQ(seen.report.status, robot::ActionStatus::collision);
  EXPECT_EQ(seen.report.reason, "the arm touched the table");
  EXPECT_TRUE(seen.recorded);
  EXPECT_FALSE(seen.classified);
  EXPECT_EQ(seen.observation_name, "none");
  EXPECT_THROW(environment.execute(0, rng), std::logic_error);  // the trial has ended
  fs::remove_all(dir);
}

bool mentions(const std::string& message, const std::string& what) {
  return message.find(what) != std::string::npos;
}

TEST(EnvironmentFactory, AProblemObjectWithNoCatalogueEntryIsAnError) {
  pomdp::ObjectProblemData d = calibrated_problem(mug_or_cup(), *model());
  d.objects.push_back("teapot");
  d.prior = {0.4, 0.4, 0.2};
  for (auto& block : d.observation_table) block.push_back(block.back());
  for (auto& row : d.sorting_reward) row.push_back(-100);
  const auto problem = std::make_shared<pomdp::ObjectIdentificationModel>(d);
  const std::string e =
      input_error_message([&] { make_environment_factory(simulator_settings(problem)); });
  EXPECT_TRUE(mentions(e, "'teapot'") && mentions(e, "catalogue")) << e;
}

TEST(EnvironmentFactory, AModelTrainedForOtherActionsOrObjectsIsAnError) {
  // Trained on strikes only, asked to classify slides too.
  const auto strikes_only = testing::train_small_model(kObjects, {"strike"}, 2);
  LoopSettings settings = simulator_settings(calibrated(mug_or_cup()).model);
  settings.classifier = strikes_only;
  std::string e = input_error_message([&] { make_environment_factory(settings); });
  EXPECT_TRUE(mentions(e, "no classifier for sensing action 'slide'")) << e;

  // Trained on the mug and the cup, planning for the mug and the can.
  pomdp::ObjectProblemData can_or_mug = mug_or_cup({"coffee_mug", "pringles_can"});
  can_or_mug.observation_symbols = {"coffee_mug", "pringles_can", "unknown"};
  for (auto& block : can_or_mug.observation_table)
    for (auto& row : block) row = {0.45, 0.45, 0.1};
  settings = simulator_settings(std::make_shared<pomdp::ObjectIdentificationModel>(can_or_mug));
  e = input_error_message([&] { make_environment_factory(settings); });
  EXPECT_TRUE(mentions(e, "reports 'plastic_cup'") && mentions(e, "other objects")) << e;
}

TEST(EnvironmentFactory, UnknownNeedsAnUnknownSymbol) {
  // The hand-tuned kind of table: the objects as symbols and no `unknown`, with a rejecting model.
  LoopSettings settings =
      simulator_settings(std::make_shared<pomdp::ObjectIdentificationModel>(mug_or_cup()));
  const std::string e = input_error_message([&] { make_environment_factory(settings); });
  EXPECT_TRUE(mentions(e, "no 'unknown' observation symbol")) << e;
}

TEST(EnvironmentFactory, AReplayFolderWithoutAnObjectIsAnError) {
  const fs::path dir = testing::unique_temp_dir("replay_missing");
  testing::write_small_dataset(dir, {"coffee_mug"}, {"slide", "strike"}, 1, 9);
  LoopSettings settings = simulator_settings(calibrated(mug_or_cup()).model);
  settings.world.kind = WorldSettings::Kind::replay;
  settings.world.recordings = dir.string();
  const std::string e = input_error_message([&] { make_environment_factory(settings); });
  EXPECT_TRUE(mentions(e, (dir / "plastic_cup").string())) << e;
  settings.world.recordings = (dir / "nowhere").string();
  EXPECT_TRUE(
      mentions(input_error_message([&] { make_environment_factory(settings); }), "nowhere"));
  fs::remove_all(dir);
}

TEST(EnvironmentFactory, ATabularProblemIsAnError) {
  const pomdp::Problem tiger =
      pomdp::load_problem(std::string(ECHOPLAN_SOURCE_DIR) + "/problems/tiger.pomdp");
  const std::string e =
      input_error_message([&] { make_environment_factory(simulator_settings(tiger.model)); });
  EXPECT_TRUE(mentions(e, "object-identification problem")) << e;
}

TEST(EnvironmentFactory, EachCallBuildsAnIndependentEnvironment) {
  const pomdp::Problem problem = calibrated(mug_or_cup());
  const auto factory = make_environment_factory(simulator_settings(problem.model));
  auto a = factory(), b = factory();
  ASSERT_NE(a.get(), b.get());
  // The same trial seed in two environments hears the same strike: nothing is shared between them.
  std::vector<LoopStep> heard;
  for (auto* env : {a.get(), b.get()}) {
    env->set_step_listener([&](const LoopStep& s) { heard.push_back(s); });
    Rng rng(8);
    env->reset(problem.model->sample_initial_state(rng), rng);
    env->execute(1, rng);
  }
  ASSERT_EQ(heard.size(), 2u);
  EXPECT_EQ(heard[0].clip.samples, heard[1].clip.samples);
  EXPECT_EQ(heard[0].observation, heard[1].observation);
}

}  // namespace
}  // namespace echoplan::experiment
