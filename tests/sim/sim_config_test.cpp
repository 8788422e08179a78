#include "sim/sim_config.h"

#include <gtest/gtest.h>

#include <cmath>

#include "common/error.h"

namespace echoplan::sim {
namespace {

TEST(SimConfig, EmptyTextGivesDefaults) {
  const SimConfig c = parse_sim_config("", "c.yaml");
  EXPECT_DOUBLE_EQ(c.variability.impact_speed.mean, 0.10);
  EXPECT_EQ(c.recording.sample_rate, 44100);
}

TEST(SimConfig, FieldsOverrideDefaults) {
  const SimConfig c = parse_sim_config(R"(variability:
  impact_speed: {mean: 0.2, spread: 0.02}
microphone:
  position: [1, 2, 3]
recording:
  noise_dbfs: -80
physics:
  timestep_s: 0.001
)",
                                       "c.yaml");
  EXPECT_DOUBLE_EQ(c.variability.impact_speed.mean, 0.2);
  EXPECT_DOUBLE_EQ(c.variability.impact_speed.spread, 0.02);
  EXPECT_DOUBLE_EQ(c.microphone.position[2], 3);
  EXPECT_DOUBLE_EQ(c.recording.noise_dbfs, -80);
  EXPECT_DOUBLE_EQ(c.physics.timestep_s, 0.001);
  EXPECT_DOUBLE_EQ(c.variability.push_speed.mean, 0.05);  // untouched
}

TEST(SimConfig, ErrorsNameFileLineAndField) {
  auto error_of = [](const std::string& text) {
    try {
      parse_sim_config(text, "c.yaml");
    } catch (const InputError& e) {
      return e;
    }
    ADD_FAILURE() << text;
    return InputError("", 0, "");
  };
  const InputError misspelt = error_of("variability:\n  impact_sped: {mean: 0.1, spread: 0}\n");
  EXPECT_EQ(misspelt.file(), "c.yaml");
  EXPECT_EQ(misspelt.line(), 2);
  EXPECT_NE(misspelt.problem().find("unknown field 'variability.impact_sped'"), std::string::npos);
  const InputError range = error_of("physics:\n  timestep_s: 0.1\n");
  EXPECT_EQ(range.line(), 2);
  EXPECT_NE(range.problem().find("physics.timestep_s"), std::string::npos);
  EXPECT_NE(error_of("variability:\n  push_speed: 0.1\n").problem().find("{mean: ..., spread: ...}"), std::string::npos);
  EXPECT_NE(error_of("colour: red\n").problem().find("unknown section"), std::string::npos);
  EXPECT_NE(error_of("microphone:\n  position: [1, 2]\n").problem().find("[x, y, z]"), std::string::npos);
}

TEST(SimConfig, TrialsAreReproducibleAndWithinThreeSpreads) {
  VariabilityConfig v;
  Rng a(42), b(42);
  for (int i = 0; i < 200; ++i) {
    const TrialParameters p = sample_trial(v, a);
    const TrialParameters q = sample_trial(v, b);
    EXPECT_EQ(p.named(), q.named());
    EXPECT_LE(std::abs(p.impact_speed - v.impact_speed.mean), 3 * v.impact_speed.spread + 1e-15);
    EXPECT_LE(std::abs(p.grasp_height - v.grasp_height.mean), 3 * v.grasp_height.spread + 1e-15);
    EXPECT_GE(p.impact_tilt_deg, 0.0);
  }
}

TEST(SimConfig, StandardNormalHasUnitMoments) {
  // 100000 draws: the sample mean's standard error is 0.003, the variance's 0.0045; 5 sigma bounds.
  Rng rng(1);
  double sum = 0, sum2 = 0;
  const int n = 100000;
  for (int i = 0; i < n; ++i) {
    const double x = standard_normal(rng);
    sum += x;
    sum2 += x * x;
  }
  EXPECT_NEAR(sum / n, 0.0, 0.016);
  EXPECT_NEAR(sum2 / n, 1.0, 0.023);
}

}  // namespace
}  // namespace echoplan::sim
