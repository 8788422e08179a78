#include "sim/sound_microphone.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace echoplan::sim {
namespace {

TEST(SoundMicrophone, LimiterKeepsEveryPeakUnderTheCeilingAndLeavesQuietSoundAlone) {
  RecordingConfig rec;  // ceiling -3 dBFS
  const int rate = 44100;
  std::array<std::vector<float>, 2> channels;
  for (auto& c : channels) {
    c.assign(rate, 0.0f);
    for (std::size_t i = 0; i < c.size(); ++i) c[i] = static_cast<float>(0.01 * std::sin(0.05 * i));
    for (std::size_t i = 20000; i < 20100; ++i) c[i] = (i % 2 ? 1.0f : -1.0f);  // a loud burst
  }
  const auto before = channels;
  apply_limiter(rec, rate, channels);
  const float ceiling = static_cast<float>(std::pow(10.0, rec.limiter_ceiling_dbfs / 20.0));
  for (const auto& c : channels)
    for (float x : c) EXPECT_LE(std::abs(x), ceiling * 1.0001f);
  // Untouched until its look-ahead reaches the burst; then held down after it.
  const auto ahead = static_cast<std::size_t>(rec.limiter_lookahead_s * rate);
  for (std::size_t i = 0; i + ahead < 20000; ++i) ASSERT_EQ(channels[0][i], before[0][i]) << i;
  EXPECT_LT(std::abs(channels[0][20200]), 0.9 * std::abs(before[0][20200]));
  // A sound under the ceiling passes exactly.
  std::array<std::vector<float>, 2> quiet{std::vector<float>(1000, 0.3f),
                                          std::vector<float>(1000, -0.3f)};
  const auto unchanged = quiet;
  apply_limiter(rec, rate, quiet);
  EXPECT_EQ(quiet, unchanged);
}

TEST(SoundMicrophone, RecorderOpensWithZerosAndClipsAtFullScale) {
  RecordingConfig rec;
  rec.lead_in_s = 0.01;
  Rng rng(1);
  NoiseSource noise(rng);
  const std::array<std::vector<float>, 2> heard{std::vector<float>(100, 2.0f),
                                                std::vector<float>(100, -2.0f)};
  const audio::AudioClip clip = recorder_output(heard, rec, -200, noise);
  const std::size_t lead = 441;
  ASSERT_EQ(clip.frames(), lead + 100);
  for (std::size_t i = 0; i < 2 * lead; ++i) ASSERT_EQ(clip.samples[i], 0.0f);
  EXPECT_EQ(clip.samples[2 * lead], 32767.0f / 32768.0f);
  EXPECT_EQ(clip.samples[2 * lead + 1], -1.0f);
}

}  // namespace
}  // namespace echoplan::sim
