// The slide's friction excitation follows the load: (mu N / reference)^exponent times the
// load-independent roughness noise, sample by sample.
#include "sim/sound_friction.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "common/rng.h"

namespace echoplan::sim {
namespace {

TEST(FrictionLoad, ScalesAsTheFrictionForceOverTheReferenceToTheExponent) {
  // mu N = 0.5 x 1.6 N = 0.8 N, four times the 0.2 N reference: 4^0.5 = 2.
  EXPECT_DOUBLE_EQ((FrictionLoad{0.5, 0.5, 0.2}.scale(1.6)), 2.0);
  // Exponent 1: 4; exponent 0: the load does not matter, as long as the surfaces touch.
  EXPECT_DOUBLE_EQ((FrictionLoad{0.5, 1.0, 0.2}.scale(1.6)), 4.0);
  EXPECT_DOUBLE_EQ((FrictionLoad{0.5, 0.0, 0.2}.scale(1.6)), 1.0);
  EXPECT_DOUBLE_EQ((FrictionLoad{0.5, 0.5, 0.2}.scale(0.0)), 0.0);
}

// A push at a steady 5 cm/s for 0.3 s, the object pressing with `force`.
ContactTrace steady_push(double force) {
  ContactTrace t;
  t.timestep_s = 0.003;
  t.steps = 100;
  t.sliding_speed.assign(t.steps, 0.05);
  t.normal_force.assign(t.steps, force);
  t.joint_speed.assign(t.steps, 0.0);
  return t;
}

TEST(FrictionLoad, ScalesTheExcitationOfTheSameSurfaceSampleBySample) {
  // Same random surface (same seed): a mug-like 3.3 N at mu 0.35 against the 0.2 N reference is
  // (1.155 / 0.2)^0.45 = 2.20 times the load-independent excitation at every sample.
  const std::size_t frames = 44100 * 3 / 10;
  auto excitation = [&](const FrictionLoad& load) {
    Rng rng(3);
    NoiseSource noise(rng);
    return friction_excitation(steady_push(3.3), 44100, frames, 1.0, load, noise);
  };
  const std::vector<float> plain = excitation({0.35, 0.0, 0.2});
  const std::vector<float> loaded = excitation({0.35, 0.45, 0.2});
  const double expected = std::pow(0.35 * 3.3 / 0.2, 0.45);
  double energy = 0;
  for (std::size_t n = 0; n < frames; ++n) {
    EXPECT_NEAR(loaded[n], expected * plain[n], 1e-5 * std::abs(plain[n]) + 1e-12) << n;
    energy += plain[n] * plain[n];
  }
  EXPECT_GT(energy, 0.0);
}

}  // namespace
}  // namespace echoplan::sim
