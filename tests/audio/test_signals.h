// Test signals and checks shared by the audio tests: tones, seeded noise, InputError messages.
#pragma once

#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>
#include <vector>

#include "../common/input_error_message.h"
#include "common/rng.h"

namespace echoplan::audio::testing {

// `n` samples of a sine of `hz` at `rate`, amplitude `amplitude` full scale.
inline std::vector<float> tone(int rate, double hz, std::size_t n, double amplitude = 0.5) {
  std::vector<float> x(n);
  for (std::size_t i = 0; i < n; ++i)
    x[i] = static_cast<float>(amplitude *
                              std::sin(2 * std::numbers::pi * hz * static_cast<double>(i) / rate));
  return x;
}

// `n` samples uniform in [-0.5, 0.5), from `seed`.
inline std::vector<float> noise(std::size_t n, std::uint64_t seed) {
  Rng rng(seed);
  std::vector<float> x(n);
  for (float& v : x) v = static_cast<float>(uniform01(rng) - 0.5);
  return x;
}

using echoplan::input_error_message;

}  // namespace echoplan::audio::testing
