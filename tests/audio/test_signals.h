// Test signals and checks shared by the audio tests: tones, seeded noise, InputError messages.
#pragma once

#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>
#include <vector>

#include "common/error.h"
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

// The message of the InputError `fn` throws, or "(no InputError)".
template <typename Fn>
std::string input_error_message(Fn fn) {
  try {
    fn();
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no InputError)";
}

}  // namespace echoplan::audio::testing
