#include "sim/sound_impacts.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "sound_measures.h"

namespace echoplan::sim {
namespace {

TEST(SoundImpacts, OnePointDrivesEveryRingModeAndAnEvenRimCancels) {
  const double floor = 0.15;
  const std::vector<RimContact> point{{0.3, 2.0}};
  for (int n = 0; n <= 4; ++n) EXPECT_DOUBLE_EQ(ring_excitation(point, n, floor), 1.0) << n;
  // Two opposite points: in phase for n = 2, cancelling for n = 1 (down to the floor).
  const std::vector<RimContact> opposite{{0.0, 1.0}, {std::numbers::pi, 1.0}};
  EXPECT_NEAR(ring_excitation(opposite, 1, floor), floor, 1e-12);
  EXPECT_NEAR(ring_excitation(opposite, 2, floor), 1.0, 1e-12);
  // A flat landing, four equal points round the rim: ring mode 2 hears only the floor.
  std::vector<RimContact> flat;
  for (int i = 0; i < 4; ++i) flat.push_back({i * std::numbers::pi / 2, 1.0});
  EXPECT_NEAR(ring_excitation(flat, 2, floor), floor, 1e-12);
  EXPECT_NEAR(ring_excitation(flat, 2, 0.0), 0.0, 1e-12);
}

TEST(SoundImpacts, PulseSpectrumFallsAboveTheContactsFrequency) {
  const double tau = 0.5e-3;
  EXPECT_NEAR(hertz_pulse_envelope(1.0, tau), 1.0, 1e-9);
  // Twelve dB per octave far above pi / tau (the half-sine's fall-off).
  const double omega = 20 * std::numbers::pi / tau;
  EXPECT_NEAR(hertz_pulse_envelope(omega, tau) / hertz_pulse_envelope(2 * omega, tau), 4.0, 0.01);
}

TEST(SoundImpacts, ContactRingsAtItsHalfPeriodAndDiesAtItsDecay) {
  // tau 0.7 ms: a tone at 1 / (2 tau) = 714 Hz, dying at 50/s (43 dB in 0.1 s).
  const int rate = 44100;
  const double tau = 0.7e-3, decay = 50;
  std::vector<float> out(rate / 2, 0.0f);
  add_contact_ring(3.0, 0.03, tau, decay, 100, rate, out);
  for (std::size_t n = 0; n < 100; ++n) EXPECT_EQ(out[n], 0.0f);  // nothing before its sample
  double bin = 0;
  const auto mag = magnitude_spectrum(out, rate, 100, out.size() - 100, &bin);
  const auto peak = std::max_element(mag.begin() + 1, mag.end()) - mag.begin();
  EXPECT_NEAR(peak * bin, 0.5 / tau, 0.01 / tau);
  const std::vector<double> level = frame_levels_db(out, rate, 0.01);
  EXPECT_NEAR(level[1] - level[11], 20 * std::log10(std::exp(decay * 0.1)), 1.0);
  // Twice the gain, twice the amplitude.
  std::vector<float> louder(out.size(), 0.0f);
  add_contact_ring(6.0, 0.03, tau, decay, 100, rate, louder);
  EXPECT_NEAR(frame_levels_db(louder, rate, 0.01)[1] - level[1], 20 * std::log10(2.0), 0.01);
}

}  // namespace
}  // namespace echoplan::sim
