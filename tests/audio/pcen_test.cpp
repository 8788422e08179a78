// PCEN against its defining equations worked out here in closed form (not by running the
// recursion): the smoother's coefficient for librosa's defaults, a constant input's
// steady state, the exact response to a step, and what makes it a front end against
// noise: stationary backgrounds 60 dB apart map to nearly the same value while an event stands out
// above them.
#include "audio/pcen.h"

#include <gtest/gtest.h>

#include <cmath>

#include "common/error.h"

namespace echoplan::audio {
namespace {

FeatureMatrix constant_energies(std::size_t rows, std::size_t cols, float value) {
  FeatureMatrix m;
  m.resize(rows, cols);
  std::fill(m.values.begin(), m.values.end(), value);
  return m;
}

// The steady state of a constant energy e: the average equals e.
double pcen_steady_state(double e, const PcenConfig& c = {}) {
  return std::pow(e / std::pow(c.eps + e, c.gain) + c.bias, c.power) - std::pow(c.bias, c.power);
}

TEST(Pcen, SmoothingIsLibrosasForItsDefaultTimeConstant) {
  // 0.4 s at a 10 ms hop: T = 40 frames, s = (sqrt(6401) - 1) / 3200.
  EXPECT_NEAR(pcen_smoothing(0.4, 0.01), 0.024689453048712014, 1e-15);
  // A longer time constant averages more slowly.
  EXPECT_LT(pcen_smoothing(2.0, 0.01), pcen_smoothing(0.4, 0.01));
}

TEST(Pcen, AConstantEnergyStaysAtItsSteadyState) {
  const FeatureMatrix out = pcen(constant_energies(30, 3, 1000.0f), 0.01, PcenConfig{});
  EXPECT_NEAR(pcen_steady_state(1000.0), 0.3600901377785144, 1e-12);  // worked out by hand
  for (float v : out.values) EXPECT_NEAR(v, 0.3600901377785144, 1e-5);
}

TEST(Pcen, AStepIsFollowedAsTheExponentialAverageSays) {
  // E = 100 for frames 0-9, then 10000: the average after the step is
  // M[9 + j] = 10000 + (100 - 10000) (1 - s)^j.
  FeatureMatrix e = constant_energies(60, 1, 100.0f);
  for (std::size_t t = 10; t < 60; ++t) e.at(t, 0) = 10000.0f;
  const double s = pcen_smoothing(0.4, 0.01);
  const FeatureMatrix out = pcen(e, 0.01, PcenConfig{});
  for (std::size_t j : {1, 2, 10, 50}) {
    const double m = 10000.0 + (100.0 - 10000.0) * std::pow(1.0 - s, static_cast<double>(j));
    const double expected = std::sqrt(10000.0 / std::pow(1e-6 + m, 0.98) + 2.0) - std::sqrt(2.0);
    EXPECT_NEAR(out.at(9 + j, 0), expected, 1e-4 * expected) << "frame " << 9 + j;
  }
  // The frame of the step stands far above the steady state it relaxes to.
  EXPECT_GT(out.at(10, 0), 5.0 * pcen_steady_state(10000.0));
}

TEST(Pcen, StationaryBackgroundsFarApartMapNearlyTogetherAndAnEventStandsOut) {
  // 60 dB between the quiet and the loud room: PCEN leaves 0.32 against 0.41 (gain 0.98 keeps
  // E^0.02 of the level); a frame 100 times its background
  // reads over 10 times either (its own energy already lifts the average it is divided by).
  const double quiet = pcen_steady_state(1.0), loud = pcen_steady_state(1e6);
  EXPECT_NEAR(quiet, std::sqrt(3.0) - std::sqrt(2.0), 1e-5);
  EXPECT_LT(loud - quiet, 0.1);
  FeatureMatrix e = constant_energies(50, 1, 1e6f);
  e.at(40, 0) = 1e8f;
  const FeatureMatrix out = pcen(e, 0.01, PcenConfig{});
  EXPECT_NEAR(out.at(39, 0), loud, 1e-4);
  EXPECT_GT(out.at(40, 0), 10.0 * loud);
}

TEST(Pcen, FramesBeforeTheStartAreZeroAndDoNotCount) {
  // Digital silence, then a constant: started at the first sound, every frame after it is
  // at the steady state; started at frame 0, the first sound is divided by an average
  // that has barely begun to rise.
  FeatureMatrix e = constant_energies(20, 2, 500.0f);
  for (std::size_t t = 0; t < 5; ++t) e.at(t, 0) = e.at(t, 1) = 0.0f;
  const FeatureMatrix started = pcen(e, 0.01, PcenConfig{}, PcenStart{5, {}});
  for (std::size_t t = 0; t < 5; ++t) EXPECT_EQ(started.at(t, 0), 0.0f);
  for (std::size_t t = 5; t < 20; ++t)
    EXPECT_NEAR(started.at(t, 1), pcen_steady_state(500.0), 1e-5);
  const FeatureMatrix from_zero = pcen(e, 0.01, PcenConfig{});
  EXPECT_GT(from_zero.at(5, 0), 10.0 * pcen_steady_state(500.0));
}

TEST(Pcen, AGivenStartAverageIsTheBackgroundBeforeTheFirstFrame) {
  // Started at an average of 100 under a constant 10000: the step of the test above, seen
  // from its first frame, M[j] = 10000 + (100 - 10000) (1 - s)^(j + 1).
  const FeatureMatrix out =
      pcen(constant_energies(20, 1, 10000.0f), 0.01, PcenConfig{}, PcenStart{0, {100.0}});
  const double s = pcen_smoothing(0.4, 0.01);
  for (std::size_t j : {0, 5, 19}) {
    const double m = 10000.0 + (100.0 - 10000.0) * std::pow(1.0 - s, static_cast<double>(j + 1));
    const double expected = std::sqrt(10000.0 / std::pow(1e-6 + m, 0.98) + 2.0) - std::sqrt(2.0);
    EXPECT_NEAR(out.at(j, 0), expected, 1e-4 * expected) << "frame " << j;
  }
}

TEST(Pcen, RefusesParametersOutOfRange) {
  const FeatureMatrix e = constant_energies(4, 1, 1.0f);
  auto with = [](auto change) {
    PcenConfig c;
    change(c);
    return c;
  };
  EXPECT_THROW(pcen(e, 0.01, with([](PcenConfig& c) { c.gain = 0.0; })), InputError);
  EXPECT_THROW(pcen(e, 0.01, with([](PcenConfig& c) { c.power = 1.5; })), InputError);
  EXPECT_THROW(pcen(e, 0.01, with([](PcenConfig& c) { c.bias = 0.0; })), InputError);
  EXPECT_THROW(pcen(e, 0.01, with([](PcenConfig& c) { c.eps = -1.0; })), InputError);
  EXPECT_THROW(pcen(e, 0.01, with([](PcenConfig& c) { c.time_constant_s = 0.0; })), InputError);
  EXPECT_THROW(pcen(e, 0.0, PcenConfig{}), InputError);
  EXPECT_THROW(pcen(e, 0.01, PcenConfig{}, PcenStart{4, {}}), InputError);
  EXPECT_THROW(pcen(e, 0.01, PcenConfig{}, PcenStart{0, {1.0, 1.0}}), InputError);
  EXPECT_EQ(pcen(FeatureMatrix{}, 0.01, PcenConfig{}).rows, 0u);
}

}  // namespace
}  // namespace echoplan::audio
