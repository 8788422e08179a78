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
#include "mug_or_cup.h"
#include "pomdp/problem.h"
#include "robot/classifier_service.h"
#include "robot/replay_recorder.h"
#include "robot/simulated_world.h"

namespace echoplan::loop {
namespace {

namespace fs = std::filesystem;

using namespace test;

// The simulated robot's parts for a world of `problem`'s sorting actions.
RobotParts simulated_parts(const pomdp::ObjectIdentificationModel& problem) {
  auto world = std::make_shared<robot::SimulatedWorld>(testing::shipped_catalogue(),
                                                       sim::SimConfig{}, problem.data().sorting);
  return {std::make_unique<robot::SimulatedArm>(world),
          std::make_unique<robot::SimulatedMicrophone>(world),
          std::make_unique<robot::ClassifierService>(model()), RecordingChecks{}};
}

// Runs one trial per object (trial k holds object k) through a Loop in `world`.
std::vector<Trial> run_each_object(std::shared_ptr<const pomdp::Problem> problem, WorldSpec world,
                                   int max_steps = 30) {
  LoopSettings settings;
  settings.problem = std::move(problem);
  settings.world = std::move(world);
  settings.observation_model = model();
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

// An observation service that sees what the world gave it and answers a fixed class, as the ROS
// observation node answers from a robot's other sensors.
class SensorService final : public robot::ObservationService {
 public:
  robot::HeardObservation observe(const audio::AudioClip& clip,
                                  const std::string& action) override {
    calls.push_back({action, clip.frames()});
    robot::HeardObservation heard;
    heard.label = "plastic_cup";
    heard.probability = 0.75;
    heard.probabilities = {{"coffee_mug", 0.25}, {"plastic_cup", 0.75}};
    return heard;
  }
  std::vector<std::pair<std::string, std::size_t>> calls;  // action, clip frames
};

TEST(RobotWorld, ARobotWithoutMicrophoneIsObservedWithoutAClip) {
  const auto problem = calibrated(mug_or_cup());
  RobotParts parts;
  parts.robot = std::make_unique<CollidingRobot>();  // a slide is done
  auto service = std::make_unique<SensorService>();
  const SensorService& seen = *service;
  parts.service = std::move(service);
  RobotWorld world(problem->model, std::move(parts));  // no recorder
  Rng rng(4);
  world.reset(problem->model->sample_initial_state(rng), rng);
  const WorldStep slide = world.execute(0, rng);
  ASSERT_TRUE(slide.robot.has_value());
  EXPECT_FALSE(slide.robot->recorded);
  EXPECT_TRUE(slide.robot->classified);
  EXPECT_EQ(slide.robot->clip.frames(), 0u);
  ASSERT_EQ(seen.calls.size(), 1u);
  EXPECT_EQ(seen.calls[0], (std::pair<std::string, std::size_t>{"slide", 0}));
  const auto& m = world.model();
  EXPECT_EQ(m.spec().observation.names[slide.outcome.observation.index], "plastic_cup");
  EXPECT_EQ(slide.outcome.heard_probability, 0.75);
  // A collision without a microphone ends the trial as with one, and nothing is observed.
  const WorldStep strike = world.execute(1, rng);
  EXPECT_TRUE(strike.outcome.terminal);
  EXPECT_FALSE(strike.robot->classified);
  EXPECT_EQ(seen.calls.size(), 1u);
}

}  // namespace
}  // namespace echoplan::loop
