// A recorder heard through background noise (robot/noisy_recorder.h), over the replay recorder:
// the folder holds one recording of each action, so what comes back minus that recording is the
// noise added.
#include "robot/noisy_recorder.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "../common/test_folder.h"
#include "audio/io.h"
#include "audio/levels.h"
#include "robot/replay_recorder.h"

namespace echoplan::robot {
namespace {

namespace fs = std::filesystem;

class NoisyFolder : public TestFolder {
 protected:
  void SetUp() override {
    TestFolder::SetUp();
    for (const char* action : {"slide", "strike"}) {
      fs::create_directories(dir_ / "mug" / action);
      audio::AudioClip clip{16000, 1, std::vector<float>(8000, 0.0f)};
      const double hz = action == std::string("slide") ? 300.0 : 900.0;
      for (std::size_t n = 2000; n < 4000; ++n)
        clip.samples[n] = static_cast<float>(0.1 * std::sin(2 * M_PI * hz * n / 16000.0));
      audio::write_audio((dir_ / "mug" / action / "0.wav").string(), clip);
    }
  }
  NoisyRecorder recorder(const std::string& ebr) const {
    return NoisyRecorder(
        std::make_unique<ReplayRecorder>(dir_),
        {std::make_shared<const sim::BackgroundNoise>(std::vector<std::string>{"white", "room"}),
         sim::parse_ebr(ebr)});
  }
  audio::AudioClip hear(NoisyRecorder& r, const std::string& action) const {
    r.start(action);
    return r.stop();
  }
  audio::AudioClip recording(const std::string& action) const {
    return audio::read_audio((dir_ / "mug" / action / "0.wav").string());
  }
};

// What was added to `quiet` to make `heard`: its RMS over the clip.
double added_rms(const audio::AudioClip& quiet, const audio::AudioClip& heard) {
  double sum = 0.0;
  for (std::size_t i = 0; i < quiet.samples.size(); ++i) {
    const double d = static_cast<double>(heard.samples[i]) - quiet.samples[i];
    sum += d * d;
  }
  return std::sqrt(sum / static_cast<double>(quiet.samples.size()));
}

// The pairing a campaign relies on: a trial's first slide hears the same noise on every arm,
// whatever the arm did before it; the next slide, and another trial, hear other noise.
TEST_F(NoisyFolder, APerformanceHearsTheSameNoiseWhateverTheTrialDidBefore) {
  NoisyRecorder first = recorder("6"), second = recorder("6");
  first.begin_trial({0, "mug", 7});
  second.begin_trial({0, "mug", 7});
  const audio::AudioClip slide = hear(first, "slide");
  hear(second, "strike");
  EXPECT_EQ(hear(second, "slide").samples, slide.samples);
  EXPECT_NE(hear(first, "slide").samples, slide.samples);  // the trial's second slide
  first.begin_trial({1, "mug", 8});
  EXPECT_NE(hear(first, "slide").samples, slide.samples);
  first.begin_trial({2, "mug", 7});  // the same trial seed again: the same noise again
  EXPECT_EQ(hear(first, "slide").samples, slide.samples);
}

// The noise is mixed at the ratio asked, over the event the inner recorder heard; a range's ratio
// is drawn inside it and reported with the source.
TEST_F(NoisyFolder, TheNoiseIsAtTheRatioAskedOverTheRecordedEvent) {
  NoisyRecorder fixed = recorder("0");
  fixed.begin_trial({0, "mug", 3});
  const audio::AudioClip quiet = recording("strike");
  const audio::AudioClip heard = hear(fixed, "strike");
  EXPECT_NEAR(20 * std::log10(audio::event_level(quiet) / added_rms(quiet, heard)), 0.0, 0.01);
  EXPECT_EQ(fixed.last_mix().ebr_db, 0.0);
  NoisyRecorder ranged = recorder("-6:12");
  ranged.begin_trial({0, "mug", 3});
  for (int i = 0; i < 10; ++i) {
    const audio::AudioClip h = hear(ranged, "slide");
    const double ebr = ranged.last_mix().ebr_db;
    EXPECT_GE(ebr, -6.0);
    EXPECT_LE(ebr, 12.0);
    EXPECT_TRUE(ranged.last_mix().source == "white" || ranged.last_mix().source == "room");
    const audio::AudioClip q = recording("slide");
    EXPECT_NEAR(20 * std::log10(audio::event_level(q) / added_rms(q, h)), ebr, 0.01);
  }
}

// The recording says how noisy it is: the ratio measured from the clip alone follows the ratio
// mixed in (stationary white noise: the background is the noise; the event window holds event and
// noise, so at 0 dB it measures about 3 dB more).
TEST_F(NoisyFolder, TheMeasuredRatioFollowsTheRatioMixedIn) {
  double last = 1e9;
  for (const char* ebr : {"24", "12", "0"}) {
    NoisyRecorder r(
        std::make_unique<ReplayRecorder>(dir_),
        {std::make_shared<const sim::BackgroundNoise>(std::vector<std::string>{"white"}),
         sim::parse_ebr(ebr)});
    r.begin_trial({0, "mug", 11});
    const double measured = audio::measured_ebr_db(hear(r, "strike"));
    EXPECT_NEAR(measured, std::stod(ebr), 4.0) << ebr;
    EXPECT_LT(measured, last);
    last = measured;
  }
}

TEST(NoisyRecorder, NeedsARecorderAndSources) {
  EXPECT_THROW(NoisyRecorder(nullptr, {}), std::invalid_argument);
}

}  // namespace
}  // namespace echoplan::robot
