// The arm's sensors (sim/arm_sensors.h) against what mechanics says they must read: the wrist
// carries the lifted object's weight, the pad pushes against the object's friction on the table,
// and the joints carry more when the object is heavier.
#include "sim/arm_sensors.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "common/error.h"
#include "shipped_catalogue.h"
#include "sim/simulated_recordings.h"
#include "sim/simulated_robot.h"

namespace echoplan::sim {
namespace {

constexpr double kGravity = 9.81;

// The mean of `channel` over the samples with t in [from, to].
double mean_between(const signal::Series& s, const std::string& channel, double from, double to) {
  const auto& v = s.values[static_cast<std::size_t>(s.channel_index(channel))];
  double sum = 0;
  int n = 0;
  for (std::size_t i = 0; i < s.samples(); ++i)
    if (s.t[i] >= from && s.t[i] <= to) sum += v[i], ++n;
  EXPECT_GT(n, 0) << channel << " in [" << from << ", " << to << "]";
  return n > 0 ? sum / n : 0.0;
}

TEST(ArmSensors, ReadEveryJointAndForceAxisAtTheConfiguredRateFromTheActionsStart) {
  SimConfig config;
  config.sensors.rate_hz = 50;
  SimulatedRobot robot(shipped_catalogue(), "coffee_mug", config);
  const ActionOutcome out = robot.execute(SoundAction::strike, nominal_trial());
  const ArmReadings& r = out.readings;
  EXPECT_EQ(r.effort.channels,
            (std::vector<std::string>{"j1", "j2", "j3", "j4", "j5", "j6", "j7"}));
  EXPECT_EQ(r.force.channels, (std::vector<std::string>{"force_x", "force_y", "force_z"}));
  ASSERT_GT(r.effort.samples(), 10u);
  EXPECT_EQ(r.effort.t, r.force.t);
  for (std::size_t i = 0; i < r.effort.samples(); ++i)
    EXPECT_DOUBLE_EQ(r.effort.t[i], static_cast<double>(i) / 50);
  // One reading per 20 ms over the whole action (its last step may fall just short of a sample).
  EXPECT_NEAR(static_cast<double>(r.effort.samples()), out.duration_s * 50 + 1, 1.0);
  signal::check_series(r.effort, "effort");
  signal::check_series(r.force, "force");
}

// The strike grasps (0.1 s), lifts (0.65 s), pauses 0.1 s, then comes down: in the pause the
// hand holds the object still, so the wrist reads its weight, downward. While the grip tightens
// the table still carries part of it: the wrist reads between nothing (the hand open at the
// start: 2% of the grip after the first step) and the whole weight.
TEST(ArmSensors, TheWristCarriesTheLiftedObjectsWeight) {
  for (const char* name : {"coffee_mug", "coffee_mug_weighted", "plastic_cup"}) {
    SimulatedRobot robot(shipped_catalogue(), name, SimConfig{});
    const ActionOutcome out = robot.execute(SoundAction::strike, nominal_trial());
    const double weight = robot.object().total_mass() * kGravity;
    EXPECT_NEAR(mean_between(out.readings.force, "force_z", 0.78, 0.84), -weight, 0.05 * weight)
        << name;
    EXPECT_NEAR(mean_between(out.readings.force, "force_x", 0.78, 0.84), 0.0, 0.05 * weight)
        << name;
    EXPECT_NEAR(mean_between(out.readings.force, "force_z", 0.0, 0.0), 0.0, 0.05 * weight) << name;
    const double gripping = mean_between(out.readings.force, "force_z", 0.05, 0.05);
    EXPECT_LT(gripping, -0.05 * weight) << name;
    EXPECT_GT(gripping, -weight) << name;
  }
}

// A slide pushes the object along +x at a steady speed between its speed-up (first 40% of the
// push) and its slow-down (last 20%): the object pushes back on the pad with its sliding friction,
// mu m g, along -x.
TEST(ArmSensors, ThePadPushesAgainstTheObjectsFrictionOnTheTable) {
  for (const char* name : {"coffee_mug", "pringles_can"}) {
    SimulatedRobot robot(shipped_catalogue(), name, SimConfig{});
    const ActionOutcome out = robot.execute(SoundAction::slide, nominal_trial());
    const double push_s = 0.051 / nominal_trial().push_speed;
    const double friction = robot.object().friction * robot.object().total_mass() * kGravity;
    EXPECT_NEAR(mean_between(out.readings.force, "force_x", 0.45 * push_s, 0.75 * push_s),
                -friction, 0.2 * friction)
        << name;
  }
}

// The joints carry the object's weight through the arm: holding the weighted mug (0.1 kg more)
// loads the shoulder joints more than holding the mug, and both more than the open hand did.
TEST(ArmSensors, TheJointsCarryMoreForAHeavierObject) {
  auto load = [](const char* name) {
    SimulatedRobot robot(shipped_catalogue(), name, SimConfig{});
    const ActionOutcome out = robot.execute(SoundAction::strike, nominal_trial());
    double change = 0;  // N m, over the shoulder and elbow joints
    for (const char* j : {"j2", "j4"})
      change += std::abs(mean_between(out.readings.effort, j, 0.78, 0.84) -
                         mean_between(out.readings.effort, j, 0.0, 0.03));
    return change;
  };
  const double mug = load("coffee_mug"), weighted = load("coffee_mug_weighted");
  EXPECT_GT(mug, 0.05);
  EXPECT_GT(weighted, mug * 1.1);
}

TEST(ArmSensors, NoiseHasTheConfiguredSpreadAndFollowsTheSeed) {
  SimulatedRobot robot(shipped_catalogue(), "coffee_mug", SimConfig{});
  const ActionOutcome out = robot.execute(SoundAction::slide, nominal_trial());
  SensorConfig sensors;
  sensors.effort_noise_nm = 0.5;
  sensors.force_noise_n = 2.0;
  ArmReadings noisy = out.readings, again = out.readings;
  Rng rng(7), same(7);
  add_sensor_noise(noisy, sensors, rng);
  add_sensor_noise(again, sensors, same);
  EXPECT_EQ(noisy.effort.values, again.effort.values);
  auto spread = [](const signal::Series& a, const signal::Series& b) {
    double squares = 0;
    int n = 0;
    for (std::size_t c = 0; c < a.channels.size(); ++c)
      for (std::size_t i = 0; i < a.samples(); ++i, ++n)
        squares += std::pow(a.values[c][i] - b.values[c][i], 2);
    return std::sqrt(squares / n);
  };
  // Hundreds of draws: the sample standard deviation within 10% of the configured one.
  EXPECT_NEAR(spread(noisy.effort, out.readings.effort), 0.5, 0.05);
  EXPECT_NEAR(spread(noisy.force, out.readings.force), 2.0, 0.2);
}

// Asking for the sensors adds their files and leaves the sound as it was (their noise has a
// stream of its own); a tree of sensors alone lists each performance by its first series.
TEST(ArmSensors, SimulatedRecordingsWriteTheSensorsBesideTheSoundOrAlone) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / "echoplan_arm_sensors_test";
  fs::remove_all(dir);
  SimulatedRecordingsOptions options;
  options.objects = {"coffee_mug"};
  options.actions = {"strike"};
  options.per_pair = 1;
  options.seed = 5;
  const std::atomic<bool> stop{false};
  options.output_dir = (dir / "audio").string();
  write_simulated_recordings(shipped_catalogue(), SimConfig{}, options, {}, stop);
  options.output_dir = (dir / "all").string();
  options.signals = {"audio", "effort", "force"};
  write_simulated_recordings(shipped_catalogue(), SimConfig{}, options, {}, stop);
  options.output_dir = (dir / "haptic").string();
  options.signals = {"force", "effort"};
  write_simulated_recordings(shipped_catalogue(), SimConfig{}, options, {}, stop);

  auto bytes = [](const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  };
  const std::string wav = "coffee_mug/strike/000.wav";
  EXPECT_EQ(bytes(dir / "audio" / wav), bytes(dir / "all" / wav));
  EXPECT_FALSE(fs::exists(dir / "audio/coffee_mug/strike/000.effort.csv"));
  const signal::Series effort =
      signal::read_series_csv((dir / "all/coffee_mug/strike/000.effort.csv").string());
  EXPECT_EQ(effort.channels.size(), 7u);
  EXPECT_EQ(bytes(dir / "all/coffee_mug/strike/000.force.csv"),
            bytes(dir / "haptic/coffee_mug/strike/000.force.csv"));
  EXPECT_FALSE(fs::exists(dir / "haptic" / wav));
  std::ifstream manifest(dir / "haptic/manifest.csv");
  std::string header, row;
  std::getline(manifest, header);
  std::getline(manifest, row);
  EXPECT_EQ(row.rfind("coffee_mug/strike/000.force.csv,", 0), 0u) << row;

  options.signals = {"audio", "torque"};
  EXPECT_THROW(write_simulated_recordings(shipped_catalogue(), SimConfig{}, options, {}, stop),
               InputError);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace echoplan::sim
