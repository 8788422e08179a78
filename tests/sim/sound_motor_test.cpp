#include "sim/sound_motor.h"

#include <gtest/gtest.h>

#include <vector>

#include "sound_measures.h"

namespace echoplan::sim {
namespace {

// The arm turning at 1 rad/s for 0.5 s, then still.
ContactTrace moving_arm() {
  ContactTrace trace;
  trace.steps = 500;
  trace.timestep_s = 0.002;
  trace.joint_speed.assign(500, 0.0);
  std::fill(trace.joint_speed.begin(), trace.joint_speed.begin() + 250, 1.0);
  return trace;
}

// Power of `x` in [lo, hi) Hz.
double band_power(const std::vector<float>& x, int rate, double lo, double hi) {
  double bin = 0, sum = 0;
  const auto mag = magnitude_spectrum(x, rate, 0, x.size(), &bin, 1);
  for (std::size_t k = 0; k < mag.size(); ++k)
    if (k * bin >= lo && k * bin < hi) sum += mag[k] * mag[k];
  return sum;
}

TEST(SoundMotor, AStillArmIsSilentAMovingOneHumsInItsBand) {
  RecordingConfig rec;
  rec.motor_noise_gain = 1;
  Rng rng(1);
  NoiseSource noise(rng);
  ContactTrace still = moving_arm();
  std::fill(still.joint_speed.begin(), still.joint_speed.end(), 0.0);
  std::vector<float> silent(rec.sample_rate, 0.0f);
  add_motor_noise(still, rec, noise, silent);
  EXPECT_EQ(silent, std::vector<float>(rec.sample_rate, 0.0f));

  std::vector<float> hum(rec.sample_rate, 0.0f);
  add_motor_noise(moving_arm(), rec, noise, hum);
  const std::vector<double> level = frame_levels_db(hum, rec.sample_rate, 0.05);
  // Rising while the arm moves, dying away after it stops (0.4 s release).
  EXPECT_GT(level[8], level[1]);
  EXPECT_LT(level[19], level[9] - 6);
  // Its power lies in the two octaves around motor_noise_hz (1.2 kHz) more than in those below
  // and above; moved to 4.8 kHz, the band follows.
  const double mid = band_power(hum, rec.sample_rate, 600, 2400);
  EXPECT_GT(mid, band_power(hum, rec.sample_rate, 150, 600));
  EXPECT_GT(mid, band_power(hum, rec.sample_rate, 2400, 9600));
  rec.motor_noise_hz = 4800;
  std::vector<float> high(rec.sample_rate, 0.0f);
  add_motor_noise(moving_arm(), rec, noise, high);
  EXPECT_GT(band_power(high, rec.sample_rate, 2400, 9600),
            band_power(high, rec.sample_rate, 600, 2400));
}

}  // namespace
}  // namespace echoplan::sim
