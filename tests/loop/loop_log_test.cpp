// LoopLog: the closed loop's per-step files, against rows written out by hand from the format in
// loop_log.h, on the shipped seed problem (objects pringles_can, coffee_mug, plastic_cup,
// paper_base).
#include "experiment/loop_log.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "../common/test_folder.h"
#include "audio/io.h"
#include "common/error.h"
#include "pomdp/problem.h"

namespace echoplan::experiment {
namespace {

namespace fs = std::filesystem;

const pomdp::ObjectIdentificationModel& seed_model() {
  static const pomdp::Problem problem =
      pomdp::load_problem(std::string(ECHOPLAN_SOURCE_DIR) + "/problems/audio_objects.yaml");
  return dynamic_cast<const pomdp::ObjectIdentificationModel&>(*problem.model);
}

std::string slurp(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// A strike heard as the mug (p 0.8125), then move_to_B ending the trial.
LoopStep strike_step() {
  LoopStep s;
  s.trial = 2;
  s.step = 0;
  s.action = 1;
  s.action_name = "strike";
  s.report = {"strike", robot::ActionStatus::done, "", 0.5};
  s.recorded = true;
  s.clip.sample_rate = 8000;
  s.clip.channels = 2;
  s.clip.samples = {0.0f, 0.25f, -0.5f, 0.5f, 0.125f, -0.25f};  // 3 frames
  s.classified = true;
  s.heard.label = "coffee_mug";
  s.heard.probability = 0.8125;
  s.heard.probabilities = {{"coffee_mug", 0.8125}, {"plastic_cup", 0.1875}};
  s.heard.distance = 1.5;
  s.heard.features = {{"onset_s", 0.25}};
  s.observation_name = "coffee_mug";
  s.reward = -1;
  s.observe_ms = 3.5;
  return s;
}

LoopStep sort_step() {
  LoopStep s;
  s.trial = 2;
  s.step = 1;
  s.action = 3;
  s.action_name = "move_to_B";
  s.report = {"move_to_B", robot::ActionStatus::done, "", 0.0};
  s.observation_name = "none";
  s.reward = 100;
  s.terminal = true;
  return s;
}

using LoopLogTest = TestFolder;

TEST_F(LoopLogTest, CsvRowsClipsAndJsonOfATrial) {
  const std::vector<double> before = {0.25, 0.25, 0.25, 0.25};
  const std::vector<double> after = {0.125, 0.5, 0.3125, 0.0625};
  nlohmann::json strike, sort;
  {
    LoopLog log(dir_, seed_model());
    strike = log.write_step(strike_step(), before, &after);
    sort = log.write_step(sort_step(), after, nullptr);
  }
  EXPECT_EQ(slurp(dir_ / "loop_steps.csv"),
            "trial,step,action,status,heard,probability,observation,p_pringles_can,p_coffee_mug,"
            "p_plastic_cup,p_paper_base,reward,clip\n"
            "2,0,strike,done,coffee_mug,0.8125,coffee_mug,0.1250,0.5000,0.3125,0.0625,-1,"
            "clips/002_00_strike.wav\n"
            "2,1,move_to_B,done,,,none,,,,,100,\n");

  // The clip as recorded (16-bit PCM: these samples are exact multiples of 2^-15).
  const audio::AudioClip clip = audio::read_audio((dir_ / "clips/002_00_strike.wav").string());
  EXPECT_EQ(clip.sample_rate, 8000);
  EXPECT_EQ(clip.channels, 2);
  EXPECT_EQ(clip.samples, strike_step().clip.samples);
  EXPECT_FALSE(fs::exists(dir_ / "clips/002_01_move_to_B.wav"));

  // loop_steps.jsonl holds the objects write_step() returned, one a line.
  std::istringstream lines(slurp(dir_ / "loop_steps.jsonl"));
  std::string line;
  std::vector<nlohmann::json> rows;
  while (std::getline(lines, line)) rows.push_back(nlohmann::json::parse(line));
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0], strike);
  EXPECT_EQ(rows[1], sort);

  EXPECT_EQ(strike["report"],
            nlohmann::json({{"status", "done"}, {"reason", ""}, {"duration_s", 0.5}}));
  EXPECT_EQ(strike["belief_before"]["coffee_mug"], 0.25);
  EXPECT_EQ(strike["belief_after"]["plastic_cup"], 0.3125);
  EXPECT_EQ(strike["clip"], "clips/002_00_strike.wav");
  EXPECT_EQ(strike["heard"]["probabilities"],
            nlohmann::json({{"coffee_mug", 0.8125}, {"plastic_cup", 0.1875}}));
  EXPECT_EQ(strike["heard"]["observe_ms"], 3.5);
  EXPECT_EQ(strike["features"], nlohmann::json({{"onset_s", 0.25}}));
  EXPECT_TRUE(sort["belief_after"].is_null());
  EXPECT_TRUE(sort["clip"].is_null());
  EXPECT_FALSE(sort.contains("heard"));
  EXPECT_EQ(sort["terminal"], true);
}

TEST_F(LoopLogTest, ACollisionIsLoggedWithItsReason) {
  LoopStep s = sort_step();
  s.action_name = "slide";
  s.report = {"slide", robot::ActionStatus::collision, "the arm touched the table", 0.25};
  s.reward = -200;
  {
    LoopLog log(dir_, seed_model());
    const nlohmann::json j = log.write_step(s, {0.25, 0.25, 0.25, 0.25}, nullptr);
    EXPECT_EQ(j["report"]["status"], "collision");
    EXPECT_EQ(j["report"]["reason"], "the arm touched the table");
  }
  const std::string text = slurp(dir_ / "loop_steps.csv");
  EXPECT_EQ(text.substr(text.find('\n') + 1), "2,1,slide,collision,,,none,,,,,-200,\n");
}

TEST_F(LoopLogTest, AFolderThatCannotBeCreatedIsAnInputError) {
  std::ofstream(dir_ / "a_file") << "";
  EXPECT_THROW(LoopLog(dir_ / "a_file" / "out", seed_model()), InputError);
}

}  // namespace
}  // namespace echoplan::experiment
