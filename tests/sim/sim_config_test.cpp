#include "sim/sim_config.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <tuple>
#include <vector>

#include "../common/source_dir.h"
#include "common/error.h"

namespace echoplan::sim {
namespace {

TEST(SimConfig, EmptyTextGivesDefaults) {
  const SimConfig c = parse_sim_config("", "c.yaml");
  EXPECT_DOUBLE_EQ(c.variability.impact_speed.mean, 0.10);
  EXPECT_EQ(c.recording.sample_rate, 44100);
}

TEST(SimConfig, ShippedExampleStatesTheDefaults) {
  // objects/sim_config.yaml documents the defaults: loading it must change nothing.
  const SimConfig c = load_sim_config(echoplan::testing::source_dir() + "/objects/sim_config.yaml");
  const SimConfig d;
  Rng a(3), b(3);
  EXPECT_EQ(sample_action(c.variability, a).named(), sample_action(d.variability, b).named());
  EXPECT_EQ(c.microphone.position, d.microphone.position);
  EXPECT_EQ(c.recording.sample_rate, d.recording.sample_rate);
  const std::vector<std::tuple<const char*, double, double>> fields{
      {"capsule_spacing", c.microphone.capsule_spacing, d.microphone.capsule_spacing},
      {"rt60_s", c.room.rt60_s, d.room.rt60_s},
      {"length_s", c.room.length_s, d.room.length_s},
      {"taps_per_s", c.room.taps_per_s, d.room.taps_per_s},
      {"reverb_level", c.room.reverb_level, d.room.reverb_level},
      {"first_reflection_s", c.room.first_reflection_s, d.room.first_reflection_s},
      {"duration_s", c.recording.duration_s, d.recording.duration_s},
      {"noise_dbfs", c.recording.noise_dbfs, d.recording.noise_dbfs},
      {"noise_corner_hz", c.recording.noise_corner_hz, d.recording.noise_corner_hz},
      {"output_gain", c.recording.output_gain, d.recording.output_gain},
      {"friction_gain", c.recording.friction_gain, d.recording.friction_gain},
      {"motor_noise_gain", c.recording.motor_noise_gain, d.recording.motor_noise_gain},
      {"limiter_ceiling_dbfs", c.recording.limiter_ceiling_dbfs, d.recording.limiter_ceiling_dbfs},
      {"limiter_hold_s", c.recording.limiter_hold_s, d.recording.limiter_hold_s},
      {"limiter_release_s", c.recording.limiter_release_s, d.recording.limiter_release_s},
      {"limiter_lookahead_s", c.recording.limiter_lookahead_s, d.recording.limiter_lookahead_s},
      {"motor_noise_hz", c.recording.motor_noise_hz, d.recording.motor_noise_hz},
      {"motor_noise_q", c.recording.motor_noise_q, d.recording.motor_noise_q},
      {"motor_attack_s", c.recording.motor_attack_s, d.recording.motor_attack_s},
      {"motor_release_s", c.recording.motor_release_s, d.recording.motor_release_s},
      {"contact_ring_gain", c.recording.contact_ring_gain, d.recording.contact_ring_gain},
      {"table_impact_gain", c.recording.table_impact_gain, d.recording.table_impact_gain},
      {"ring_mode_floor", c.recording.ring_mode_floor, d.recording.ring_mode_floor},
      {"friction_direct_gain", c.recording.friction_direct_gain, d.recording.friction_direct_gain},
      {"friction_load_exponent", c.recording.friction_load_exponent,
       d.recording.friction_load_exponent},
      {"friction_reference_force_n", c.recording.friction_reference_force_n,
       d.recording.friction_reference_force_n},
      {"grasp_time_s", c.arm.grasp_time_s, d.arm.grasp_time_s},
      {"strike_ease_s", c.arm.strike_ease_s, d.arm.strike_ease_s},
      {"lift_pause_s", c.arm.lift_pause_s, d.arm.lift_pause_s},
      {"level_time_s", c.arm.level_time_s, d.arm.level_time_s},
      {"hold_time_s", c.arm.hold_time_s, d.arm.hold_time_s},
      {"release_time_s", c.arm.release_time_s, d.arm.release_time_s},
      {"push_accelerate_share", c.arm.push_accelerate_share, d.arm.push_accelerate_share},
      {"push_decelerate_share", c.arm.push_decelerate_share, d.arm.push_decelerate_share},
      {"timestep_s", c.physics.timestep_s, d.physics.timestep_s},
      {"slide_timestep_s", c.physics.slide_timestep_s, d.physics.slide_timestep_s},
      {"rate_hz", c.sensors.rate_hz, d.sensors.rate_hz},
      {"effort_noise_nm", c.sensors.effort_noise_nm, d.sensors.effort_noise_nm},
      {"force_noise_n", c.sensors.force_noise_n, d.sensors.force_noise_n}};
  for (const auto& [name, shipped, built_in] : fields) EXPECT_DOUBLE_EQ(shipped, built_in) << name;
}

TEST(SimConfig, FieldsOverrideDefaults) {
  const SimConfig c = parse_sim_config(R"(variability:
  impact_speed: {mean: 0.2, stddev: 0.02}
microphone:
  position: [1, 2, 3]
recording:
  noise_dbfs: -80
arm:
  push_accelerate_share: 0.6
  push_decelerate_share: 0.4
physics:
  timestep_s: 0.001
  slide_timestep_s: 0.0025
sensors: {rate_hz: 200, force_noise_n: 0}
)",
                                       "c.yaml");
  EXPECT_DOUBLE_EQ(c.variability.impact_speed.mean, 0.2);
  EXPECT_DOUBLE_EQ(c.variability.impact_speed.stddev, 0.02);
  EXPECT_DOUBLE_EQ(c.microphone.position[2], 3);
  EXPECT_DOUBLE_EQ(c.recording.noise_dbfs, -80);
  EXPECT_DOUBLE_EQ(c.physics.timestep_s, 0.001);
  EXPECT_DOUBLE_EQ(c.physics.slide_timestep_s, 0.0025);
  EXPECT_DOUBLE_EQ(c.arm.push_accelerate_share, 0.6);
  EXPECT_DOUBLE_EQ(c.arm.push_decelerate_share, 0.4);
  EXPECT_DOUBLE_EQ(c.sensors.rate_hz, 200);
  EXPECT_DOUBLE_EQ(c.sensors.force_noise_n, 0);
  EXPECT_DOUBLE_EQ(c.sensors.effort_noise_nm, SimConfig{}.sensors.effort_noise_nm);
  EXPECT_DOUBLE_EQ(c.variability.push_speed.mean,
                   SimConfig{}.variability.push_speed.mean);  // untouched
}

TEST(SimConfig, TableIsANameOrAList) {
  EXPECT_TRUE(parse_sim_config("", "c.yaml").tables.empty());
  EXPECT_EQ(parse_sim_config("table: steel_bench\n", "c.yaml").tables,
            (std::vector<std::string>{"steel_bench"}));
  EXPECT_EQ(parse_sim_config("table: [oak_top, rubber_mat]\n", "c.yaml").tables,
            (std::vector<std::string>{"oak_top", "rubber_mat"}));
  try {
    parse_sim_config("room: {rt60_s: 0.3}\ntable: [oak_top, oak_top]\n", "c.yaml");
    ADD_FAILURE() << "no error for a table named twice";
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 2) << e.what();
  }
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
  const InputError misspelt = error_of("variability:\n  impact_sped: {mean: 0.1, stddev: 0}\n");
  EXPECT_EQ(misspelt.file(), "c.yaml");
  EXPECT_EQ(misspelt.line(), 2);
  EXPECT_NE(misspelt.problem().find("unknown key 'impact_sped' in variability (expected one of: "),
            std::string::npos)
      << misspelt.what();
  const InputError range = error_of("physics:\n  timestep_s: 0.1\n");
  EXPECT_EQ(range.line(), 2);
  EXPECT_NE(range.problem().find("physics.timestep_s"), std::string::npos);
  const InputError slide_step = error_of("physics:\n  timestep_s: 0.002\n  slide_timestep_s: 0\n");
  EXPECT_EQ(slide_step.line(), 3);
  EXPECT_NE(slide_step.problem().find("physics.slide_timestep_s"), std::string::npos)
      << slide_step.what();
  const InputError rate = error_of("sensors:\n  effort_noise_nm: 0\n  rate_hz: 5\n");
  EXPECT_EQ(rate.line(), 3);
  EXPECT_NE(rate.problem().find("sensors.rate_hz"), std::string::npos) << rate.what();
  const InputError share = error_of("arm:\n  push_accelerate_share: 1.5\n");
  EXPECT_EQ(share.line(), 2);
  EXPECT_NE(share.problem().find("arm.push_accelerate_share"), std::string::npos) << share.what();
  // Each share in range, but together more than the push.
  const InputError shares =
      error_of("arm:\n  push_accelerate_share: 0.7\n  push_decelerate_share: 0.4\n");
  EXPECT_EQ(shares.line(), 2);
  EXPECT_NE(shares.problem().find("add up to more than 1"), std::string::npos) << shares.what();
  const InputError corner = error_of("recording:\n  sample_rate: 44100\n  noise_corner_hz: -50\n");
  EXPECT_EQ(corner.line(), 3);
  EXPECT_NE(corner.problem().find("recording.noise_corner_hz"), std::string::npos) << corner.what();
  // Every tuned constant the config carries is checked against its range, naming its line.
  const std::vector<std::pair<std::string, std::string>> out_of_range{
      {"room", "first_reflection_s: 0.2"},
      {"recording", "limiter_lookahead_s: 1"},
      {"recording", "motor_noise_hz: 5"},
      {"recording", "motor_noise_q: 0"},
      {"recording", "motor_attack_s: 0"},
      {"recording", "motor_release_s: 20"},
      {"recording", "contact_ring_gain: -1"},
      {"recording", "table_impact_gain: 11"},
      {"recording", "ring_mode_floor: 1.5"},
      {"recording", "friction_direct_gain: -0.5"},
      {"recording", "friction_load_exponent: 1.5"},
      {"recording", "friction_reference_force_n: 0"},
      {"arm", "grasp_time_s: 0"},
      {"arm", "strike_ease_s: 3"},
      {"arm", "lift_pause_s: -1"},
      {"arm", "level_time_s: 5"},
      {"arm", "hold_time_s: 0.001"},
      {"arm", "release_time_s: 10"}};
  for (const auto& [section, line] : out_of_range) {
    const InputError e = error_of("# my lab\n" + section + ":\n  " + line + "\n");
    EXPECT_EQ(e.line(), 3) << line;
    const std::string field = section + "." + line.substr(0, line.find(':'));
    EXPECT_NE(e.problem().find(field), std::string::npos) << e.what();
  }
  // The motor band must lie below the recording's Nyquist frequency.
  const InputError band = error_of("recording:\n  sample_rate: 8000\n  motor_noise_hz: 5000\n");
  EXPECT_EQ(band.line(), 3);
  EXPECT_NE(band.problem().find("recording.motor_noise_hz"), std::string::npos) << band.what();
  EXPECT_NE(
      error_of("variability:\n  push_speed: 0.1\n").problem().find("{mean: ..., stddev: ...}"),
      std::string::npos);
  EXPECT_NE(error_of("colour: red\n").problem().find("unknown key 'colour' in the sim config"),
            std::string::npos);
  // Keys that are not names are bad input, not internal errors (found by fuzz/sim_files_fuzz.cpp).
  EXPECT_EQ(error_of("variability:\n  ? [a]\n  : 1\n").line(), 2);
  EXPECT_EQ(error_of("? [a]\n: 1\n").line(), 1);
  EXPECT_NE(error_of("microphone:\n  position: [1, 2]\n").problem().find("[x, y, z]"),
            std::string::npos);
}

TEST(SimConfig, TrialsAreReproducibleAndWithinThreeSpreads) {
  VariabilityConfig v;
  Rng a(42), b(42);
  for (int i = 0; i < 200; ++i) {
    const ActionVariation p = sample_action(v, a);
    const ActionVariation q = sample_action(v, b);
    EXPECT_EQ(p.named(), q.named());
    EXPECT_LE(std::abs(p.impact_speed - v.impact_speed.mean), 3 * v.impact_speed.stddev + 1e-15);
    EXPECT_LE(std::abs(p.grasp_height - v.grasp_height.mean), 3 * v.grasp_height.stddev + 1e-15);
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
