// The world factory: each world kind checked against the problem and the classifier before any
// trial, then built anew for every caller.
#include "loop/world_spec.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "../common/input_error_message.h"
#include "../common/source_dir.h"
#include "../robot/small_training_set.h"
#include "common/error.h"
#include "loop/calibrated_problem.h"
#include "mug_or_cup.h"
#include "pomdp/problem.h"

namespace echoplan::loop {
namespace {

namespace fs = std::filesystem;

using namespace test;

WorldInputs simulator_inputs(pomdp::ModelPtr problem) {
  return {simulator(), problem, model(), {}, std::nullopt};
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
  settings.observation_model = strikes_only;
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
      pomdp::load_problem(echoplan::testing::source_dir() + "/problems/tiger.pomdp");
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

TEST(WorldFactory, NamesEachWorld) {
  EXPECT_EQ(world_name(TableWorldSpec{}), "model");
  EXPECT_EQ(world_name(simulator()), "simulated");
  EXPECT_EQ(world_name(ReplayWorldSpec{"dir"}), "replay");
  EXPECT_EQ(world_name(PartsWorldSpec{{}, "ros"}), "ros");
}

TEST(WorldFactory, ATableWorldNeedsNoClassifierAndDrawsFromTheProblem) {
  const auto problem = calibrated(mug_or_cup());
  const auto world =
      make_world_factory({TableWorldSpec{}, problem->model, nullptr, {}, std::nullopt})();
  Rng rng(3);
  world->reset(problem->model->sample_initial_state(rng), rng);
  const WorldStep step = world->execute(1, rng);
  EXPECT_FALSE(step.robot.has_value());
  EXPECT_EQ(step.outcome.reward, -1.0);
  EXPECT_FALSE(step.outcome.terminal);
}

}  // namespace
}  // namespace echoplan::loop
