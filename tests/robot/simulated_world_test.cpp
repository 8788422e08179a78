#include "robot/simulated_world.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <set>
#include <stdexcept>

#include "../common/source_dir.h"
#include "common/error.h"
#include "sim/table_choice.h"

namespace echoplan::robot {
namespace {

const sim::Catalogue& shipped_catalogue() {
  static const sim::Catalogue c =
      sim::load_catalogue(echoplan::testing::source_dir() + "/objects/catalogue.yaml");
  return c;
}

std::shared_ptr<SimulatedWorld> make_world() {
  return std::make_shared<SimulatedWorld>(shipped_catalogue(), sim::SimConfig{},
                                          std::vector<std::string>{"move_to_A", "move_to_B"});
}

double rms(const audio::AudioClip& clip) {
  double sum = 0;
  for (float x : clip.samples) sum += static_cast<double>(x) * x;
  return std::sqrt(sum / static_cast<double>(clip.samples.size()));
}

// The background noise's RMS as configured (dB re full scale).
double noise_rms() { return std::pow(10.0, sim::SimConfig{}.recording.noise_dbfs / 20.0); }

TEST(SimulatedWorld, MicrophoneHearsTheStrikeTheArmMade) {
  auto world = make_world();
  SimulatedArm arm(world);
  SimulatedMicrophone mic(world);
  arm.begin_trial({0, "coffee_mug", 7});
  mic.start("strike");
  const ActionReport report = arm.execute("strike");
  const audio::AudioClip clip = mic.stop();
  EXPECT_EQ(report.action, "strike");
  EXPECT_EQ(report.status, ActionStatus::done);
  EXPECT_GT(report.duration_s, 1.0);  // lift, pause, descent: over a second of simulated time
  ASSERT_TRUE(world->last_outcome().has_value());
  EXPECT_FALSE(world->last_outcome()->trace.impacts.empty());
  EXPECT_EQ(clip.channels, 2);
  EXPECT_GE(clip.duration_seconds(), report.duration_s);
  // The impact is far above the room's noise floor.
  EXPECT_GT(rms(clip), 10 * noise_rms());
}

TEST(SimulatedWorld, SortingIsSilentAndMotionless) {
  auto world = make_world();
  SimulatedArm arm(world);
  SimulatedMicrophone mic(world);
  arm.begin_trial({0, "plastic_cup", 3});
  mic.start("move_to_A");
  const ActionReport report = arm.execute("move_to_A");
  const audio::AudioClip clip = mic.stop();
  EXPECT_EQ(report.status, ActionStatus::done);
  EXPECT_EQ(report.duration_s, 0.0);
  EXPECT_FALSE(world->last_outcome().has_value());
  // Only the room: the recorder's lead-in of digital zeros, then the background noise for the usual
  // recording length, at the configured level give or take the day's variation (cut at 3 standard
  // deviations).
  const sim::SimConfig config;
  EXPECT_NEAR(clip.duration_seconds(), config.recording.lead_in_s + config.recording.duration_s,
              0.01);
  const auto lead_in = static_cast<std::size_t>(config.recording.lead_in_s * clip.sample_rate) * 2;
  audio::AudioClip after = clip;
  after.samples.erase(after.samples.begin(), after.samples.begin() + lead_in);
  const double margin_db = 3 * config.variability.background_db.stddev + 0.5;
  EXPECT_GT(rms(after), noise_rms() * std::pow(10.0, -margin_db / 20));
  EXPECT_LT(rms(after), noise_rms() * std::pow(10.0, margin_db / 20));
}

TEST(SimulatedWorld, SameSeedSameSoundAndListeningDoesNotChangeThePhysics) {
  auto a = make_world(), b = make_world();
  SimulatedArm arm_a(a), arm_b(b);
  SimulatedMicrophone mic_a(a), mic_b(b);
  arm_a.begin_trial({0, "pringles_can", 11});
  arm_b.begin_trial({0, "pringles_can", 11});
  // World b executes a slide nobody hears before the strike both hear: the strike's physics must
  // not depend on whether the slide was heard, so b hears its slide too, unlike a.
  arm_a.execute("slide");
  mic_b.start("slide");
  arm_b.execute("slide");
  mic_b.stop();
  mic_a.start("strike");
  mic_b.start("strike");
  arm_a.execute("strike");
  arm_b.execute("strike");
  EXPECT_EQ(a->last_outcome()->variation.named(), b->last_outcome()->variation.named());
  EXPECT_EQ(a->last_outcome()->trace.impacts.size(), b->last_outcome()->trace.impacts.size());
  const audio::AudioClip clip_a = mic_a.stop(), clip_b = mic_b.stop();
  EXPECT_EQ(clip_a.samples.size(), clip_b.samples.size());

  // A new trial with the same seed replays the same strike bit for bit.
  arm_a.begin_trial({1, "pringles_can", 11});
  arm_a.execute("slide");
  mic_a.start("strike");
  arm_a.execute("strike");
  EXPECT_EQ(mic_a.stop().samples, clip_a.samples);
}

TEST(SimulatedWorld, TwoActionsWhileListeningAreHeardOneAfterTheOther) {
  auto world = make_world();
  SimulatedArm arm(world);
  SimulatedMicrophone mic(world);
  arm.begin_trial({0, "paper_base", 5});
  mic.start("slide");
  arm.execute("slide");
  const audio::AudioClip one = mic.stop();
  mic.start("slide");
  arm.execute("slide");
  arm.execute("strike");
  const audio::AudioClip two = mic.stop();
  EXPECT_GT(two.frames(), one.frames());
  EXPECT_NEAR(two.duration_seconds(), 2 * sim::SimConfig{}.recording.duration_s, 1.0);
}

TEST(SimulatedWorld, RejectsUnknownObjectsAndActions) {
  auto world = make_world();
  SimulatedArm arm(world);
  try {
    arm.begin_trial({0, "teapot", 1});
    FAIL() << "no error for an object the catalogue does not have";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("teapot"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("coffee_mug"), std::string::npos)
        << e.what();  // lists the known
  }
  EXPECT_THROW(arm.execute("strike"), std::logic_error);  // no trial begun
  arm.begin_trial({0, "coffee_mug", 1});
  try {
    arm.execute("shake");
    FAIL() << "no error for an unknown action";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("'shake'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("move_to_B"), std::string::npos) << e.what();
  }
  SimulatedMicrophone mic(world);
  EXPECT_THROW(mic.stop(), std::logic_error);  // stop without start
  EXPECT_THROW(SimulatedWorld(shipped_catalogue(), sim::SimConfig{}, {"strike"}), InputError);
}

TEST(SimulatedWorld, ATrialsTableIsDrawnFromItsSeedTheSameForEveryWorld) {
  // Two worlds stand for two arms of a campaign: given the trial's seed, each meets the same table
  // and hears the same strike, whatever the other trials before it were.
  sim::SimConfig config;
  config.tables = {"lab_laminate", "steel_bench", "rubber_mat"};
  const std::vector<std::string> sorting{"move_to_A", "move_to_B"};
  SimulatedWorld first(shipped_catalogue(), config, sorting);
  SimulatedWorld second(shipped_catalogue(), config, sorting);
  std::set<std::string> met;
  for (std::uint64_t seed = 1; seed <= 12; ++seed) {
    first.begin_trial({0, "plastic_cup", seed});
    second.begin_trial({0, "plastic_cup", 100 + seed});  // another trial first on this arm
    second.begin_trial({0, "plastic_cup", seed});
    EXPECT_EQ(first.surface(), second.surface()) << seed;
    EXPECT_EQ(first.surface(), sim::table_of_trial(config, seed));
    met.insert(first.surface());
    if (seed > 2) continue;
    first.start_listening();
    second.start_listening();
    const ActionReport report = first.execute("strike");
    EXPECT_EQ(report.surface, first.surface());
    second.execute("strike");
    EXPECT_EQ(first.stop_listening().samples, second.stop_listening().samples) << seed;
  }
  EXPECT_EQ(met.size(), 3u);  // 12 trials meet every table of three
}

TEST(SimulatedWorld, OnTheDefaultTableTheReportNamesNoSurface) {
  auto world = make_world();
  SimulatedArm arm(world);
  arm.begin_trial({0, "coffee_mug", 7});
  EXPECT_EQ(world->surface(), "lab_laminate");
  EXPECT_EQ(arm.execute("strike").surface, "");  // logs of the lab's table keep their bytes
}

TEST(SimulatedWorld, AnUnknownTableIsRefusedWhenTheWorldIsBuilt) {
  sim::SimConfig config;
  config.tables = {"marble"};
  EXPECT_THROW(SimulatedWorld(shipped_catalogue(), config, {"move_to_A"}), InputError);
}

}  // namespace
}  // namespace echoplan::robot
