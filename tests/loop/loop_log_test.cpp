// LoopLog: the closed loop's per-step files, against rows written out by hand from the format in
// loop_log.h, on the report's shipped problem (objects pringles_can, coffee_mug, plastic_cup,
// paper_base).
#include "loop/loop_log.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <sstream>

#include "../common/source_dir.h"
#include "../common/test_folder.h"
#include "audio/io.h"
#include "common/error.h"
#include "pomdp/problem.h"

namespace echoplan::loop {
namespace {

namespace fs = std::filesystem;

const pomdp::ObjectIdentificationModel& report_model() {
  static const pomdp::Problem problem =
      pomdp::load_problem(echoplan::testing::source_dir() + "/problems/audio_objects.yaml");
  return *problem.model->object_identification();
}

int symbol(const std::string& name) {
  const auto& names = report_model().spec().observation.names;
  return static_cast<int>(std::find(names.begin(), names.end(), name) - names.begin());
}

std::string slurp(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// A strike heard as the mug (p 0.8125), from a uniform belief to `after`.
Step strike_step() {
  Step s;
  s.record.trial = 2;
  s.record.step = 0;
  s.record.action = 1;  // strike
  s.record.belief = {0.25, 0.25, 0.25, 0.25};
  s.record.observation.index = symbol("coffee_mug");
  s.record.reward = -1;
  s.record.heard_ebr_db = 12.25;
  s.belief_after = {0.125, 0.5, 0.3125, 0.0625};
  RobotStep& r = s.robot.emplace();
  r.report = {
      .action = "strike", .status = robot::ActionStatus::done, .reason = "", .duration_s = 0.5};
  r.recorded = true;
  r.clip.sample_rate = 8000;
  r.clip.channels = 2;
  r.clip.samples = {0.0f, 0.25f, -0.5f, 0.5f, 0.125f, -0.25f};  // 3 frames
  r.classified = true;
  r.heard.label = "coffee_mug";
  r.heard.probability = 0.8125;
  r.heard.probabilities = {{"coffee_mug", 0.8125}, {"plastic_cup", 0.1875}};
  r.heard.distance = 1.5;
  r.heard.features = {{"onset_s", 0.25}};
  r.observe_ms = 3.5;
  return s;
}

// move_to_B ending the trial.
Step sort_step() {
  Step s;
  s.record.trial = 2;
  s.record.step = 1;
  s.record.action = 3;  // move_to_B
  s.record.belief = {0.125, 0.5, 0.3125, 0.0625};
  s.record.observation.index = report_model().none_symbol();
  s.record.reward = 100;
  s.terminal = true;
  s.robot.emplace().report = {
      .action = "move_to_B", .status = robot::ActionStatus::done, .reason = "", .duration_s = 0.0};
  return s;
}

using LoopLogTest = TestFolder;

TEST_F(LoopLogTest, CsvRowsClipsAndJsonOfATrial) {
  nlohmann::json strike, sort;
  {
    LoopLog log(dir_, report_model());
    strike = log.write_step(strike_step());
    sort = log.write_step(sort_step());
  }
  EXPECT_EQ(slurp(dir_ / "loop_steps.csv"),
            "trial,step,action,status,heard,probability,observation,p_pringles_can,p_coffee_mug,"
            "p_plastic_cup,p_paper_base,reward,heard_ebr_db,clip\n"
            "2,0,strike,done,coffee_mug,0.8125,coffee_mug,0.1250,0.5000,0.3125,0.0625,-1,12.2,"
            "clips/002_00_strike.wav\n"
            "2,1,move_to_B,done,,,none,,,,,100,,\n");

  // The clip as recorded (16-bit PCM: these samples are exact multiples of 2^-15).
  const audio::AudioClip clip = audio::read_audio((dir_ / "clips/002_00_strike.wav").string());
  EXPECT_EQ(clip.sample_rate, 8000);
  EXPECT_EQ(clip.channels, 2);
  EXPECT_EQ(clip.samples, strike_step().robot->clip.samples);
  EXPECT_FALSE(fs::exists(dir_ / "clips/002_01_move_to_B.wav"));

  // loop_steps.jsonl holds the objects write_step() returned, one a line.
  std::istringstream lines(slurp(dir_ / "loop_steps.jsonl"));
  std::string line;
  std::vector<nlohmann::json> rows;
  while (std::getline(lines, line)) rows.push_back(nlohmann::json::parse(line));
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0], strike);
  EXPECT_EQ(rows[1], sort);

  EXPECT_EQ(
      strike["report"],
      nlohmann::json({{"status", "done"}, {"reason", ""}, {"duration_s", 0.5}, {"attempts", 1}}));
  EXPECT_EQ(strike["fault"], nullptr);
  EXPECT_EQ(strike["belief_before"]["coffee_mug"], 0.25);
  EXPECT_EQ(strike["belief_after"]["plastic_cup"], 0.3125);
  EXPECT_EQ(strike["clip"], "clips/002_00_strike.wav");
  EXPECT_EQ(strike["heard_ebr_db"], 12.25);
  EXPECT_EQ(strike["heard"]["probabilities"],
            nlohmann::json({{"coffee_mug", 0.8125}, {"plastic_cup", 0.1875}}));
  EXPECT_EQ(strike["heard"]["observe_ms"], 3.5);
  EXPECT_EQ(strike["features"], nlohmann::json({{"onset_s", 0.25}}));
  EXPECT_TRUE(sort["belief_after"].is_null());
  EXPECT_TRUE(sort["clip"].is_null());
  EXPECT_TRUE(sort["heard_ebr_db"].is_null());
  EXPECT_FALSE(sort.contains("heard"));
  EXPECT_EQ(sort["terminal"], true);
}

TEST_F(LoopLogTest, ACollisionIsLoggedWithItsReason) {
  Step s = sort_step();
  s.record.action = 0;  // slide
  s.robot->report = {.action = "slide",
                     .status = robot::ActionStatus::collision,
                     .reason = "the arm touched the table",
                     .duration_s = 0.25};
  s.robot->recorded = false;
  s.record.reward = -200;
  {
    LoopLog log(dir_, report_model());
    const nlohmann::json j = log.write_step(s);
    EXPECT_EQ(j["report"]["status"], "collision");
    EXPECT_EQ(j["report"]["reason"], "the arm touched the table");
  }
  const std::string text = slurp(dir_ / "loop_steps.csv");
  EXPECT_EQ(text.substr(text.find('\n') + 1), "2,1,slide,collision,,,none,,,,,-200,,\n");
}

// A full disk under the step log (loop_steps.jsonl is /dev/full, where every write fails with
// ENOSPC): the step is an InputError naming the trial and the step, not rows silently lost.
TEST_F(LoopLogTest, AStepLogThatCannotBeWrittenIsAnInputErrorNamingTheTrialAndStep) {
  fs::create_directories(dir_);
  fs::create_symlink("/dev/full", dir_ / "loop_steps.jsonl");
  LoopLog log(dir_, report_model());
  Step s = sort_step();
  try {
    log.write_step(s);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(e.problem().find("trial 2, step 2: loop_steps.csv or loop_steps.jsonl could not be "
                               "written; is the disk full? 0 step(s) were logged before"),
              std::string::npos)
        << e.what();
  }
  EXPECT_EQ(log.steps_written(), 0);
}

TEST_F(LoopLogTest, AFolderThatCannotBeCreatedIsAnInputError) {
  std::ofstream(dir_ / "a_file") << "";
  EXPECT_THROW(LoopLog(dir_ / "a_file" / "out", report_model()), InputError);
}

}  // namespace
}  // namespace echoplan::loop
