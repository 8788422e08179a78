// The closed loop end to end: a Loop plans on a calibrated problem, and the robot world answers
// with the simulated robot (or replayed recordings) and the trained classifier; the worlds' checks.
#include "loop/robot_world.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "../common/input_error_message.h"
#include "../robot/small_training_set.h"
#include "audio/io.h"
#include "common/error.h"
#include "loop/calibrated_problem.h"
#include "loop/loop.h"
#include "loop/world_spec.h"
#include "pomdp/problem.h"
#include "robot/classifier_service.h"
#include "robot/replay_recorder.h"
#include "robot/simulated_world.h"

namespace echoplan::loop {
namespace {

namespace fs = std::filesystem;

const std::vector<std::string> kObjects{"coffee_mug", "plastic_cup"};

std::shared_ptr<const perception::ObservationModel> model() {
  static const auto m = testing::train_small_model(kObjects, {"slide", "strike"}, 3);
  return m;
}

// Mug or cup, sorted to A (mug) or B (cup); the report's rewards. Observation symbols and
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

std::shared_ptr<const pomdp::Problem> calibrated(const pomdp::ObjectProblemData& base) {
  auto p = std::make_shared<pomdp::Problem>();
  p->model = std::make_shared<pomdp::ObjectIdentificationModel>(calibrated_problem(base, *model()));
  p->belief.particles = 300;
  p->planner.exploration = 110;
  return p;
}

SimulatedWorldSpec simulator() {
  return {std::make_shared<const sim::Catalogue>(testing::shipped_catalogue()),
          std::make_shared<const sim::SimConfig>()};
}

WorldInputs simulator_inputs(pomdp::ModelPtr problem) {
  return {simulator(), problem, model(), {}};
}

// The simulated robot's parts for a world of `problem`'s sorting actions.
RobotParts simulated_parts(const pomdp::ObjectIdentificationModel& problem) {
  auto world = std::make_shared<robot::SimulatedWorld>(testing::shipped_catalogue(),
                                                       sim::SimConfig{}, problem.data().sorting);
  return {std::make_unique<robot::SimulatedArm>(world),
          std::make_unique<robot::SimulatedMicrophone>(world),
          std::make_unique<robot::ClassifierService>(model())};
}

// Runs one trial per object (trial k holds object k) through a Loop in `world`.
std::vector<Trial> run_each_object(std::shared_ptr<const pomdp::Problem> problem, WorldSpec world,
                                   int max_steps = 30) {
  LoopSettings settings;
  settings.problem = std::move(problem);
  settings.world = std::move(world);
  settings.classifier = model();
  settings.planner.solver = "abt";
  settings.planner.episodes = 300;
  settings.max_steps = max_steps;
  Loop loop(std::make_shared<const LoopSpec>(std::move(settings)));
  std::vector<Trial> trials;
  for (int k = 0; k < 2; ++k) {
    auto trial = loop.run({k, k, 3});
    if (trial) trials.push_back(std::move(*trial));
  }
  return trials;
}

// Each step's record and what the robot reported agree, and the trial ended by sorting.
void expect_consistent_trial(const pomdp::ObjectIdentificationModel& m, const Trial& trial) {
  ASSERT_EQ(static_cast<int>(trial.steps.size()), trial.record.steps);
  EXPECT_FALSE(trial.record.capped);
  EXPECT_FALSE(trial.record.collision);
  double discounted = 0, weight = 1;
  for (std::size_t i = 0; i < trial.steps.size(); ++i) {
    const Step& s = trial.steps[i];
    const StepRecord& r = s.record;
    ASSERT_TRUE(s.robot.has_value());
    const RobotStep& l = *s.robot;
    EXPECT_EQ(r.step, static_cast<int>(i));
    EXPECT_EQ(l.report.action, m.spec().action_names[r.action]);
    EXPECT_EQ(l.report.status, robot::ActionStatus::done);
    const bool last = i + 1 == trial.steps.size();
    EXPECT_EQ(s.terminal, last);
    EXPECT_EQ(s.belief_after.has_value(), !last);
    if (m.is_sensing(r.action)) {
      EXPECT_FALSE(last) << "a sensing action ended the trial";
      EXPECT_TRUE(l.recorded);
      EXPECT_TRUE(l.classified);
      EXPECT_GT(l.clip.frames(), 0u);
      EXPECT_EQ(m.spec().observation.names[r.observation.index],
                l.heard.unknown ? "unknown" : l.heard.label);
      EXPECT_EQ(r.reward, -1.0);
      ASSERT_TRUE(r.heard_probability.has_value());
      EXPECT_EQ(*r.heard_probability, l.heard.probability);
      EXPECT_FALSE(l.heard.features.empty());
      EXPECT_GE(l.observe_ms, 0.0);
    } else {
      EXPECT_TRUE(last) << "the trial went on after a sorting action";
      EXPECT_FALSE(l.recorded);
      EXPECT_EQ(r.observation.index, m.none_symbol());
      const int j = r.action - m.num_sensing();
      EXPECT_EQ(r.reward, m.data().sorting_reward[j][trial.record.true_state]);
    }
    discounted += weight * r.reward;
    weight *= m.spec().discount;
  }
  EXPECT_FALSE(m.is_sensing(trial.steps.back().record.action));
  EXPECT_NEAR(trial.record.discounted_reward, discounted, 1e-9);
}

TEST(RobotWorld, FullTrialsWithTheSimulatedRobotEndInSortingWithConsistentSteps) {
  const auto problem = calibrated(mug_or_cup());
  const std::vector<Trial> trials = run_each_object(problem, simulator());
  ASSERT_EQ(trials.size(), 2u);
  const auto& m = *problem->model->object_identification();
  for (std::size_t t = 0; t < trials.size(); ++t) {
    SCOPED_TRACE("trial " + std::to_string(t));
    EXPECT_EQ(trials[t].record.true_state, static_cast<int>(t));
    expect_consistent_trial(m, trials[t]);
  }
  // The planner listened before it sorted.
  EXPECT_GT(trials[0].record.steps + trials[1].record.steps, 2);
}

TEST(RobotWorld, ReplayedRecordingsDriveTheLoop) {
  const fs::path dir = testing::unique_temp_dir("replay_loop");
  testing::write_small_dataset(dir, kObjects, {"slide", "strike"}, 2, 77);
  const auto problem = calibrated(mug_or_cup());
  const std::vector<Trial> trials = run_each_object(problem, ReplayWorldSpec{dir.string()});
  ASSERT_EQ(trials.size(), 2u);
  const auto& m = *problem->model->object_identification();
  for (const Trial& trial : trials) {
    SCOPED_TRACE("trial " + std::to_string(trial.record.trial));
    expect_consistent_trial(m, trial);
    // Every clip heard is one of the true object's recordings of that action.
    const std::string object = kObjects[trial.record.true_state];
    for (const Step& s : trial.steps) {
      if (!s.robot->recorded) continue;
      const std::string& action = m.spec().action_names[s.record.action];
      bool found = false;
      for (const auto& file : fs::directory_iterator(dir / object / action))
        found = found || audio::read_audio(file.path().string()).samples == s.robot->clip.samples;
      EXPECT_TRUE(found) << action << " in trial of " << object;
    }
  }
  fs::remove_all(dir);
}

TEST(RobotWorld, AWeightedVariantStandsInForItsObject) {
  const auto problem = calibrated(mug_or_cup());
  const auto& m = *problem->model->object_identification();
  RobotWorld world(problem->model, simulated_parts(m), {{"coffee_mug", "coffee_mug_weighted"}});
  Rng rng(1);
  pomdp::State mug = problem->model->sample_initial_state(rng);
  mug.discrete[0] = 0;
  world.reset(mug, rng);
  EXPECT_EQ(world.world_object(), "coffee_mug_weighted");
  mug.discrete[0] = 1;
  world.reset(mug, rng);
  EXPECT_EQ(world.world_object(), "plastic_cup");
}

TEST(RobotWorld, ASlideMovesTheTrueStateAsTheModelSays) {
  const auto problem = calibrated(mug_or_cup());
  RobotWorld world(problem->model, simulated_parts(*problem->model->object_identification()));
  Rng rng(2);
  const pomdp::State start = problem->model->sample_initial_state(rng);
  world.reset(start, rng);
  world.execute(0, rng);  // slide: +5 cm along x
  EXPECT_NEAR(world.true_state().continuous[pomdp::ObjectIdentificationModel::kOffsetX],
              start.continuous[pomdp::ObjectIdentificationModel::kOffsetX] + 0.05, 1e-12);
  EXPECT_EQ(world.true_state().discrete, start.discrete);
}

// A robot whose strike always hits the table: the world must turn that into the model's
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

TEST(RobotWorld, ACollisionIsHeardAsNothingAndEndsTheTrial) {
  const fs::path dir = testing::unique_temp_dir("collision");
  testing::write_small_dataset(dir, kObjects, {"slide", "strike"}, 1, 5);
  const auto problem = calibrated(mug_or_cup());
  RobotParts parts;
  parts.robot = std::make_unique<CollidingRobot>();
  parts.recorder = std::make_unique<robot::ReplayRecorder>(dir);
  parts.service = std::make_unique<robot::ClassifierService>(model());
  RobotWorld world(problem->model, std::move(parts));
  Rng rng(4);
  world.reset(problem->model->sample_initial_state(rng), rng);
  const WorldStep slide = world.execute(0, rng);
  EXPECT_FALSE(slide.outcome.collision);
  EXPECT_FALSE(slide.outcome.terminal);
  const WorldStep strike = world.execute(1, rng);
  const auto& m = world.model();
  EXPECT_TRUE(strike.outcome.collision);
  EXPECT_TRUE(strike.outcome.terminal);
  EXPECT_EQ(strike.outcome.observation.index, m.none_symbol());
  EXPECT_EQ(strike.outcome.reward, m.data().collision_reward);
  ASSERT_TRUE(strike.robot.has_value());
  EXPECT_EQ(strike.robot->report.status, robot::ActionStatus::collision);
  EXPECT_EQ(strike.robot->report.reason, "the arm touched the table");
  EXPECT_TRUE(strike.robot->recorded);
  EXPECT_FALSE(strike.robot->classified);
  EXPECT_THROW(world.execute(0, rng), std::logic_error);  // the trial has ended
  fs::remove_all(dir);
}

bool mentions(const std::string& message, const std::string& what) {
  return message.find(what) != std::string::npos;
}

TEST(WorldFactory, AProblemObjectWithNoCatalogueEntryIsAnError) {
  pomdp::ObjectProblemData d = calibrated_problem(mug_or_cup(), *model());
  d.objects.push_back("teapot");
  d.prior = {0.4, 0.4, 0.2};
  for (auto& block : d.observation_table) block.push_back(block.back());
  for (auto& row : d.sorting_reward) row.push_back(-100);
  const auto problem = std::make_shared<pomdp::ObjectIdentificationModel>(d);
  const std::string e = input_error_message([&] { make_world_factory(simulator_inputs(problem)); });
  EXPECT_TRUE(mentions(e, "'teapot'") && mentions(e, "catalogue")) << e;
}

TEST(WorldFactory, AModelTrainedForOtherActionsOrObjectsIsAnError) {
  // Trained on strikes only, asked to classify slides too.
  const auto strikes_only = testing::train_small_model(kObjects, {"strike"}, 2);
  WorldInputs settings = simulator_inputs(calibrated(mug_or_cup())->model);
  settings.classifier = strikes_only;
  std::string e = input_error_message([&] { make_world_factory(settings); });
  EXPECT_TRUE(mentions(e, "no classifier for sensing action 'slide'")) << e;

  // Trained on the mug and the cup, planning for the mug and the can.
  pomdp::ObjectProblemData can_or_mug = mug_or_cup({"coffee_mug", "pringles_can"});
  can_or_mug.observation_symbols = {"coffee_mug", "pringles_can", "unknown"};
  for (auto& block : can_or_mug.observation_table)
    for (auto& row : block) row = {0.45, 0.45, 0.1};
  settings = simulator_inputs(std::make_shared<pomdp::ObjectIdentificationModel>(can_or_mug));
  e = input_error_message([&] { make_world_factory(settings); });
  EXPECT_TRUE(mentions(e, "reports 'plastic_cup'") && mentions(e, "other objects")) << e;
}

TEST(WorldFactory, UnknownNeedsAnUnknownSymbol) {
  // The hand-tuned kind of table: the objects as symbols and no `unknown`, with a rejecting model.
  const WorldInputs settings =
      simulator_inputs(std::make_shared<pomdp::ObjectIdentificationModel>(mug_or_cup()));
  const std::string e = input_error_message([&] { make_world_factory(settings); });
  EXPECT_TRUE(mentions(e, "no 'unknown' observation symbol")) << e;
}

TEST(WorldFactory, AReplayFolderWithoutAnObjectIsAnError) {
  const fs::path dir = testing::unique_temp_dir("replay_missing");
  testing::write_small_dataset(dir, {"coffee_mug"}, {"slide", "strike"}, 1, 9);
  WorldInputs settings = simulator_inputs(calibrated(mug_or_cup())->model);
  settings.spec = ReplayWorldSpec{dir.string()};
  const std::string e = input_error_message([&] { make_world_factory(settings); });
  EXPECT_TRUE(mentions(e, (dir / "plastic_cup").string())) << e;
  settings.spec = ReplayWorldSpec{(dir / "nowhere").string()};
  EXPECT_TRUE(mentions(input_error_message([&] { make_world_factory(settings); }), "nowhere"));
  fs::remove_all(dir);
}

TEST(WorldFactory, ATabularProblemIsAnError) {
  const pomdp::Problem tiger =
      pomdp::load_problem(std::string(ECHOPLAN_SOURCE_DIR) + "/problems/tiger.pomdp");
  const std::string e =
      input_error_message([&] { make_world_factory(simulator_inputs(tiger.model)); });
  EXPECT_TRUE(mentions(e, "object-identification problem")) << e;
}

TEST(WorldFactory, EachCallBuildsAnIndependentWorld) {
  const auto problem = calibrated(mug_or_cup());
  const auto factory = make_world_factory(simulator_inputs(problem->model));
  auto a = factory(), b = factory();
  ASSERT_NE(a.get(), b.get());
  // The same trial seed in two worlds hears the same strike: nothing is shared between them.
  std::vector<WorldStep> heard;
  for (auto* world : {a.get(), b.get()}) {
    Rng rng(8);
    world->reset(problem->model->sample_initial_state(rng), rng);
    heard.push_back(world->execute(1, rng));
  }
  ASSERT_TRUE(heard[0].robot && heard[1].robot);
  EXPECT_EQ(heard[0].robot->clip.samples, heard[1].robot->clip.samples);
  EXPECT_EQ(heard[0].outcome.observation, heard[1].outcome.observation);
}

}  // namespace
}  // namespace echoplan::loop
