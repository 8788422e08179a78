// The loop's observation model prepared once: loaded, trained on a folder, or trained on a training
// set the simulator synthesises; and the problem calibrated to it in memory.
#include "loop/prepare_observation.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "../common/input_error_message.h"
#include "../robot/small_training_set.h"
#include "loop/object_problem.h"
#include "perception/observation_model_json.h"

namespace echoplan::loop {
namespace {

namespace fs = std::filesystem;

const std::vector<std::string> kObjects{"coffee_mug", "plastic_cup"};

pomdp::Problem mug_or_cup() {
  return pomdp::parse_problem(R"(name: mug_or_cup
discount: 0.99
objects: [coffee_mug, plastic_cup]
actions:
  sensing: [slide, strike]
  sorting: [move_to_A, move_to_B]
initial_belief:
  type: fixed_configuration
  joints: [-2.89527, 1.45058, -0.18396, 2.07696, -0.310356, 0.630897, -1.54233]
  offset: [0.1, 0, 0]
  objects: {coffee_mug: 0.5, plastic_cup: 0.5}
transition:
  type: kinematic
  offset_change: {slide: [0.05, 0, 0], strike: [0, 0, 0]}
  collision_probability: {slide: 0, strike: 0}
observation:
  type: table
  symbols: [coffee_mug, plastic_cup]
  table:
    slide: {coffee_mug: [0.5, 0.5], plastic_cup: [0.5, 0.5]}
    strike: {coffee_mug: [0.5, 0.5], plastic_cup: [0.5, 0.5]}
reward:
  sensing: {slide: -1, strike: -1}
  sorting:
    move_to_A: {coffee_mug: 10, plastic_cup: -100}
    move_to_B: {coffee_mug: -100, plastic_cup: 10}
  collision: -100
terminal:
  type: sorting_or_collision
heuristic:
  type: known_object
belief: {type: particle, particles: 300}
)",
                              "mug_or_cup.yaml");
}

SimulatedTraining simulated(const fs::path& dir) {
  SimulatedTraining t;
  t.catalogue = std::make_shared<const sim::Catalogue>(testing::shipped_catalogue());
  t.config = std::make_shared<const sim::SimConfig>();
  t.objects = kObjects;
  t.actions = {"slide", "strike"};
  t.per_pair = 3;
  t.seed = 4;
  t.directory = dir;
  return t;
}

TEST(PrepareObservation, TrainsOnSynthesisedRecordingsAndCalibratesTheProblemInMemory) {
  const fs::path dir = testing::unique_temp_dir("prepare_simulated");
  const pomdp::Problem base = mug_or_cup();
  const std::atomic<bool> never{false};
  int synthesised = 0;
  const PreparedObservation p = prepare_observation(
      simulated(dir), &base, "out/problem.yaml",
      [&](const std::string& what, int, int total) {
        if (what != "synthesise") return;
        ++synthesised;
        EXPECT_EQ(total, 12);
      },
      never);
  ASSERT_TRUE(p.model && p.problem);
  EXPECT_EQ(synthesised, 12);
  EXPECT_TRUE(fs::exists(dir / "manifest.csv"));
  EXPECT_EQ(p.model->classes(), kObjects);
  // The problem plans with the model's table, row for row, and says where it will be saved.
  const auto& data = object_problem(*p.problem->model).data();
  EXPECT_EQ(data.observation_symbols, p.model->observation_symbols());
  EXPECT_EQ(data.observation_table[1], p.model->observation_table("strike"));
  EXPECT_EQ(p.problem->source_path, "out/problem.yaml");
  EXPECT_EQ(p.problem->belief.particles, base.belief.particles);
  fs::remove_all(dir);
}

TEST(PrepareObservation, ACompleteSetIsReusedOnlyWhenAsked) {
  const fs::path dir = testing::unique_temp_dir("prepare_reuse");
  const std::atomic<bool> never{false};
  SimulatedTraining t = simulated(dir);
  ASSERT_TRUE(synthesise_training_set(t, {}, never));
  const auto written = fs::last_write_time(dir / "coffee_mug/strike/000.wav");
  int clips = 0;
  const ProgressFn count = [&](const std::string&, int, int) { ++clips; };
  t.reuse_complete = true;
  ASSERT_TRUE(synthesise_training_set(t, count, never));
  EXPECT_EQ(clips, 0);
  EXPECT_EQ(fs::last_write_time(dir / "coffee_mug/strike/000.wav"), written);
  t.reuse_complete = false;
  ASSERT_TRUE(synthesise_training_set(t, count, never));
  EXPECT_EQ(clips, 12);
  fs::remove_all(dir);
}

TEST(PrepareObservation, AStopBeforeTrainingGivesNoModel) {
  const fs::path dir = testing::unique_temp_dir("prepare_stop");
  const std::atomic<bool> stopped{true};
  const pomdp::Problem base = mug_or_cup();
  const PreparedObservation p = prepare_observation(simulated(dir), &base, "", {}, stopped);
  EXPECT_EQ(p.model, nullptr);
  EXPECT_EQ(p.problem, nullptr);
  fs::remove_all(dir);
}

TEST(PrepareObservation, LoadsAModelFileAndSaysWhenItDoesNotFitTheProblem) {
  const fs::path dir = testing::unique_temp_dir("prepare_file");
  const auto trained = testing::train_small_model({"coffee_mug", "pringles_can"}, {"strike"}, 2);
  const std::string file = (dir / "model.json").string();
  fs::create_directories(dir);
  perception::save_observation_model(*trained, file);
  const std::atomic<bool> never{false};
  const PreparedObservation loaded = prepare_observation(ModelFile{file}, nullptr, "", {}, never);
  ASSERT_NE(loaded.model, nullptr);
  EXPECT_EQ(loaded.model->classes(), trained->classes());
  EXPECT_EQ(loaded.problem, nullptr);
  // Trained for the strike only, on the mug and the can: the mug-or-cup problem cannot use it.
  const pomdp::Problem base = mug_or_cup();
  const std::string e =
      input_error_message([&] { prepare_observation(ModelFile{file}, &base, "", {}, never); });
  EXPECT_NE(e.find("mug_or_cup.yaml"), std::string::npos) << e;
  EXPECT_NE(e.find("slide"), std::string::npos) << e;
  EXPECT_NE(input_error_message([&] {
              prepare_observation(ModelFile{(dir / "none.json").string()}, nullptr, "", {}, never);
            }).find("none.json"),
            std::string::npos);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace echoplan::loop
