// The loop's observation model prepared once: loaded, trained on a folder, or trained on a training
// set the simulator synthesises; and the problem calibrated to it in memory.
#include "loop/prepare_observation.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "../common/input_error_message.h"
#include "../robot/small_training_set.h"
#include "loop/object_problem.h"
#include "mug_or_cup.h"
#include "perception/observation_model_json.h"

namespace echoplan::loop {
namespace {

namespace fs = std::filesystem;

using test::kObjects;

// The mug-or-cup problem as if read from a file.
pomdp::Problem mug_or_cup_problem() {
  pomdp::Problem p;
  p.model = std::make_shared<pomdp::ObjectIdentificationModel>(test::mug_or_cup());
  p.belief.particles = 300;
  p.source_path = "mug_or_cup.yaml";
  return p;
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
  const pomdp::Problem base = mug_or_cup_problem();
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
  const pomdp::Problem base = mug_or_cup_problem();
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
  const pomdp::Problem base = mug_or_cup_problem();
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
