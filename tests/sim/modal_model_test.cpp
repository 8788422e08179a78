#include "sim/modal_model.h"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>

#include "sim/simulated_recorder.h"

namespace echoplan::sim {
namespace {

Material ceramic() { return {"ceramic", 2700, 7.2e10, 0.19, 6, 1e-7}; }

ObjectSpec mug() {
  ObjectSpec o;
  o.name = "mug";
  o.radius = 0.04;
  o.height = 0.1;
  o.wall_thickness = 0.005;
  o.base_thickness = 0.006;
  o.shell_mass = 0.3;
  o.material = ceramic();
  o.contact_radius = 0.004;
  o.ring_modes = 3;
  return o;
}

TEST(ModalModel, RayleighDecay) {
  // alpha/2 + beta w^2/2 at 1 kHz: 3 + 1e-7 * (2 pi 1000)^2 / 2 = 3 + 1.9739...
  EXPECT_NEAR(ceramic().decay_rate(1000.0),
              3.0 + 1e-7 * std::pow(2 * std::numbers::pi * 1000, 2) / 2, 1e-12);
}

TEST(ModalModel, RingModesFollowLovesFormula) {
  // Worked by hand for n = 2: c_b = sqrt(7.2e10 / (12 * 2700 * (1 - 0.19^2))) = 1518.2 m/s;
  // f_2 = 0.005 / (2 pi 0.0016) * 1518.37 * 6 / sqrt(5) = 2026.35 Hz.
  const auto modes = object_modes(mug(), 20000);
  ASSERT_GE(modes.size(), 2u);
  EXPECT_NEAR(modes[0].frequency_hz, 2026.35, 0.01);
  EXPECT_EQ(modes[0].azimuthal_order, 2);
  // n = 3 is n(n^2-1)/sqrt(n^2+1) = 24/sqrt(10) against 6/sqrt(5): a ratio of 2.8284.
  EXPECT_NEAR(modes[1].frequency_hz / modes[0].frequency_hz,
              24 / std::sqrt(10.0) / (6 / std::sqrt(5.0)), 1e-9);
  EXPECT_DOUBLE_EQ(modes[0].decay_per_s, ceramic().decay_rate(modes[0].frequency_hz));
}

TEST(ModalModel, ClosedTubeRingsAtHalfWavelengthCavity) {
  ObjectSpec can = mug();
  can.height = 0.23;
  can.closed = true;
  const auto modes = object_modes(can, 20000);
  int cavities = 0;
  for (const auto& m : modes)
    if (std::abs(m.frequency_hz - kSpeedOfSound / (2 * 0.23)) < 1e-9) ++cavities;
  EXPECT_EQ(cavities, 1);
  can.closed = false;
  for (const auto& m : object_modes(can, 20000))
    EXPECT_GT(std::abs(m.frequency_hz - kSpeedOfSound / (2 * 0.23)), 1.0);
}

TEST(ModalModel, ListedModesReplaceDerivedOnesAndModesAboveTheLimitAreDropped) {
  ObjectSpec o = mug();
  o.listed_modes = {{500, 1.0, 0}, {1500, 0.5, 40}, {30000, 1.0, 0}};
  const auto modes = object_modes(o, 20000);
  ASSERT_EQ(modes.size(), 2u);
  EXPECT_DOUBLE_EQ(modes[0].frequency_hz, 500);
  EXPECT_DOUBLE_EQ(modes[0].decay_per_s, ceramic().decay_rate(500));
  EXPECT_DOUBLE_EQ(modes[1].decay_per_s, 40);  // listed decay wins over the material's
}

TEST(ModalModel, HertzContactTimeScalesAsMassToTwoFifths) {
  const double e_star = effective_modulus(ceramic(), ceramic());
  // Two identical materials: E* = E / (2 (1 - nu^2)).
  EXPECT_NEAR(e_star, 7.2e10 / (2 * (1 - 0.19 * 0.19)), 1.0);
  const double t1 = hertz_contact_time(0.3, 0.004, e_star, 0.1);
  const double t2 = hertz_contact_time(0.6, 0.004, e_star, 0.1);
  EXPECT_NEAR(t2 / t1, std::pow(2.0, 0.4), 1e-12);
  EXPECT_NEAR(hertz_contact_time(0.3, 0.004, e_star, 0.2) / t1, std::pow(2.0, -0.2), 1e-12);
  // The formula's value, by hand: 2.87 * (0.09 / (0.004 * e_star^2 * 0.1))^0.2.
  EXPECT_NEAR(t1, 2.87 * std::pow(0.09 / (0.004 * e_star * e_star * 0.1), 0.2), 1e-15);
}

TEST(ModalModel, HalfSineSpectrumMatchesNumericalFourierTransform) {
  // Independent reference: integrate F(t) = (pi / 2 tau) sin(pi t / tau) e^{-i w t} over [0, tau]
  // with the midpoint rule (20000 points: error ~1e-8 relative).
  const double tau = 0.8e-3;
  for (double f : {0.0, 100.0, 625.0, 1250.0, 2000.0, 5000.0, 11000.0}) {
    const double w = 2 * std::numbers::pi * f;
    std::complex<double> sum = 0;
    const int n = 20000;
    for (int i = 0; i < n; ++i) {
      const double t = (i + 0.5) * tau / n;
      sum += std::numbers::pi / (2 * tau) * std::sin(std::numbers::pi * t / tau) *
             std::polar(1.0, -w * t) * (tau / n);
    }
    EXPECT_NEAR(half_sine_pulse_spectrum(w, tau), std::abs(sum), 1e-6) << f;
  }
}

TEST(ModalModel, SynthesisEnvelopeFollowsTheHalfSineSpectrumsLobes) {
  // Above the first zero (w tau = 3 pi) the exact spectrum's lobes peak near even x = w tau / pi at
  // 1 / (x^2 - 1), the envelope is 1 / sqrt(1 + x^4): their ratio x^2 / (x^2 - 1) is at most 16/15
  // (x = 4), so the exact spectrum stays within 7% of the envelope, and touches it at each lobe.
  const double tau = 1e-3;
  EXPECT_DOUBLE_EQ(hertz_pulse_envelope(0, tau), 1.0);
  for (double x = 3.0; x < 40.0; x += 0.01) {
    const double w = x * std::numbers::pi / tau;
    EXPECT_LE(half_sine_pulse_spectrum(w, tau), hertz_pulse_envelope(w, tau) * 1.07) << x;
  }
  for (int x = 4; x < 40; x += 2) {
    const double w = x * std::numbers::pi / tau;
    EXPECT_GE(half_sine_pulse_spectrum(w, tau), hertz_pulse_envelope(w, tau)) << x;
  }
  // A longer contact is duller: less at 3 kHz.
  EXPECT_LT(hertz_pulse_envelope(2 * std::numbers::pi * 3000, 1.2e-3),
            hertz_pulse_envelope(2 * std::numbers::pi * 3000, 1e-3));
}

}  // namespace
}  // namespace echoplan::sim
