#include "sim/arm_sensors.h"

#include <fmt/format.h>

#include <cmath>

#include "sim/scene.h"

namespace echoplan::sim {

namespace {

signal::Series empty_series(std::vector<std::string> channels) {
  signal::Series s;
  s.values.resize(channels.size());
  s.channels = std::move(channels);
  return s;
}

void add_sample(signal::Series& s, double t, const double* values) {
  s.t.push_back(t);
  for (std::size_t c = 0; c < s.channels.size(); ++c) s.values[c].push_back(values[c]);
}

void add_noise(signal::Series& s, double stddev, Rng& rng) {
  if (stddev <= 0) return;
  for (auto& channel : s.values)
    for (double& v : channel) v += stddev * standard_normal(rng);
}

}  // namespace

ArmSensorRecorder::ArmSensorRecorder(const Scene& scene, double rate_hz, ArmReadings& readings)
    : s_(scene), period_(1.0 / rate_hz), readings_(readings) {
  std::vector<std::string> joints;
  for (int i = 0; i < kArmJoints; ++i) joints.push_back(fmt::format("j{}", i + 1));
  readings_.effort = empty_series(std::move(joints));
  readings_.force = empty_series({"force_x", "force_y", "force_z"});
}

void ArmSensorRecorder::after_step(const mjModel* m, const mjData* d, double time) {
  // Half a physics step of slack: sample k is the step whose end is nearest k periods.
  if (time + 0.5 * m->opt.timestep < next_ * period_) return;
  const double t = next_ * period_;
  ++next_;
  double effort[kArmJoints];
  for (int i = 0; i < kArmJoints; ++i) effort[i] = d->qfrc_actuator[i] + d->qfrc_applied[i];
  add_sample(readings_.effort, t, effort);
  // The grasp's pull on the hand, then every contact between the arm and the object. A contact's
  // force from mj_contactForce acts on its second geom along the frame's first row (the normal
  // from geom1 to geom2); on the first geom it is the opposite.
  double force[3];
  for (int k = 0; k < 3; ++k) force[k] = d->xfrc_applied[6 * s_.hand_body + k];
  for (int i = 0; i < d->ncon; ++i) {
    const mjContact& c = d->contact[i];
    const bool arm1 = s_.is_arm_geom(c.geom1), arm2 = s_.is_arm_geom(c.geom2);
    const bool object1 = c.geom1 == s_.object_geom, object2 = c.geom2 == s_.object_geom;
    if (!((arm1 && object2) || (arm2 && object1))) continue;
    mjtNum local[6], world[3];
    mj_contactForce(m, d, i, local);
    mju_mulMatTVec(world, c.frame, local, 3, 3);  // frame rows are the contact axes
    const double sign = arm2 ? 1.0 : -1.0;
    for (int k = 0; k < 3; ++k) force[k] += sign * world[k];
  }
  add_sample(readings_.force, t, force);
}

void ArmSensorRecorder::at_rest(const mjData* d) {
  if (next_ > 0) return;
  ++next_;
  const double force[3]{0, 0, 0};
  add_sample(readings_.effort, 0.0, d->qfrc_bias);
  add_sample(readings_.force, 0.0, force);
}

void add_sensor_noise(ArmReadings& readings, const SensorConfig& sensors, Rng& rng) {
  add_noise(readings.effort, sensors.effort_noise_nm, rng);
  add_noise(readings.force, sensors.force_noise_n, rng);
}

}  // namespace echoplan::sim
