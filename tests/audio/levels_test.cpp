// A recording's levels (audio/levels.h), checked on clips whose levels are known in closed form: a
// sine's RMS is its amplitude over sqrt(2) over whole periods.
#include "audio/levels.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace echoplan::audio {
namespace {

// A clip of `seconds` at 44.1 kHz: a 1 kHz sine of amplitude `loud` from `from_s` to `to_s` and of
// amplitude `quiet` everywhere else.
AudioClip burst(double seconds, double loud, double quiet, double from_s, double to_s) {
  AudioClip clip{44100, 1, std::vector<float>(static_cast<std::size_t>(seconds * 44100))};
  for (std::size_t i = 0; i < clip.samples.size(); ++i) {
    const double t = static_cast<double>(i) / 44100;
    const double a = t >= from_s && t < to_s ? loud : quiet;
    clip.samples[i] = static_cast<float>(a * std::sin(2 * std::numbers::pi * 1000 * t));
  }
  return clip;
}

TEST(Levels, TheEventLevelIsTheLoudest50Milliseconds) {
  // The silence around the tone does not dilute it.
  EXPECT_NEAR(event_level(burst(1.0, 0.4, 0.0, 0.3, 0.5)), 0.4 / std::sqrt(2.0), 2e-3);
  EXPECT_EQ(event_level(burst(1.0, 0.0, 0.0, 0.0, 1.0)), 0.0);
  // Shorter than a window: the whole clip.
  EXPECT_NEAR(event_level(burst(0.02, 0.5, 0.0, 0.0, 0.02)), 0.5 / std::sqrt(2.0), 1e-3);
  EXPECT_EQ(event_level(AudioClip{44100, 1, {}}), 0.0);
}

TEST(Levels, TheBackgroundIsTheQuietAroundTheEvent) {
  // 0.2 s of event in 1.5 s: the quietest tenth of the windows is the background's tone alone.
  const AudioClip clip = burst(1.5, 0.4, 0.01, 0.3, 0.5);
  EXPECT_NEAR(background_level(clip), 0.01 / std::sqrt(2.0), 1e-4);
  // The ratio is the two amplitudes': 20 log10(0.4 / 0.01) = 32.04 dB.
  EXPECT_NEAR(measured_ebr_db(clip), 20 * std::log10(40.0), 0.05);
  // The event alone in the clip: the background is its own level, 0 dB.
  EXPECT_NEAR(measured_ebr_db(burst(1.0, 0.3, 0.0, 0.0, 1.0)), 0.0, 0.05);
}

TEST(Levels, ChannelsAreAveragedAndDegenerateClipsHaveFiniteRatios) {
  // Two channels in antiphase cancel: the average is silent.
  AudioClip stereo{44100, 2, {}};
  const AudioClip mono = burst(0.5, 0.4, 0.01, 0.1, 0.2);
  for (float x : mono.samples) {
    stereo.samples.push_back(x);
    stereo.samples.push_back(-x);
  }
  EXPECT_EQ(event_level(stereo), 0.0);
  EXPECT_EQ(measured_ebr_db(stereo), 0.0);
  // Digital silence around the event: no finite ratio, so the highest.
  EXPECT_EQ(measured_ebr_db(burst(1.0, 0.4, 0.0, 0.3, 0.5)), 120.0);
  EXPECT_EQ(measured_ebr_db(AudioClip{44100, 1, {}}), 0.0);
}

}  // namespace
}  // namespace echoplan::audio
