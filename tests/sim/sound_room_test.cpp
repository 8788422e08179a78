#include "sim/sound_room.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace echoplan::sim {
namespace {

TEST(SoundRoom, TapsFillTheTailAfterTheFirstReflectionAndDecay) {
  RoomConfig room;
  const int rate = 44100;
  Rng rng(2);
  const auto taps = reverb_taps(room, rate, rng);
  EXPECT_EQ(taps.size(), static_cast<std::size_t>(std::lround(room.taps_per_s * room.length_s)));
  double early = 0, late = 0;
  for (const auto& [delay, gain] : taps) {
    EXPECT_GE(delay, static_cast<std::size_t>(room.first_reflection_s * rate) - 1);
    EXPECT_LE(delay, static_cast<std::size_t>(std::lround(room.length_s * rate)));
    (delay < room.length_s * rate / 2 ? early : late) += gain * gain;
  }
  // -60 dB at rt60 0.25 s: the second 40 ms carry 10^(-6 * 0.04 / 0.25) = 0.57 of the first's
  // energy per tap; with ~20 taps each, well below the first.
  EXPECT_LT(late, early);
  // A later first reflection moves every tap after it.
  room.first_reflection_s = 0.02;
  Rng again(2);
  for (const auto& [delay, gain] : reverb_taps(room, rate, again))
    EXPECT_GE(delay, static_cast<std::size_t>(0.02 * rate) - 1);
}

TEST(SoundRoom, RoomIsTheDrySoundPlusEveryDelayedCopy) {
  std::vector<float> dry(10000);
  for (std::size_t i = 0; i < dry.size(); ++i) dry[i] = static_cast<float>(std::sin(0.01 * i));
  const std::vector<std::pair<std::size_t, float>> taps{{5, 0.5f}, {4200, -0.25f}, {9000, 0.1f}};
  std::vector<float> expected = dry;
  for (const auto& [delay, gain] : taps) add_delayed(dry, delay, gain, expected);
  EXPECT_EQ(add_room(dry, taps), expected);
  // An impulse comes back at each tap with its gain.
  std::vector<float> impulse(10000, 0.0f);
  impulse[0] = 1.0f;
  const std::vector<float> response = add_room(impulse, taps);
  EXPECT_EQ(response[0], 1.0f);
  EXPECT_EQ(response[5], 0.5f);
  EXPECT_EQ(response[4200], -0.25f);
  EXPECT_EQ(response[9000], 0.1f);
}

}  // namespace
}  // namespace echoplan::sim
