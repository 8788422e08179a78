// What the arm's own sensors read during an action, beside the microphone: the torque in each of
// its seven joints (the Jaco2 has a torque sensor in every actuator) and the force the object puts
// on the hand (a wrist force sensor), sampled from the physics at a fixed rate from the action's
// start. These are the raw signals of a recordings tree (`<name>.effort.csv`, `<name>.force.csv`,
// docs/feature-sets.md) that torque-based perception computes its features from.
//
// Joint torque: what the joint's servo applies plus the gravity and Coriolis torques the arm's
// controller compensates (a joint torque sensor reads the whole load: the arm's own weight, the
// object's when lifted, the table's push back through the hand). Wrist force: the force on the
// hand from the object (the grasp carrying it, the pad pushing it), in the world frame (a reading
// with the hand's own weight compensated, rotated into the base frame as arm controllers report
// it). Sensor noise is added when a recording is made (add_sensor_noise), not here.
#pragma once

#include <mujoco/mujoco.h>

#include "common/rng.h"
#include "signal/series.h"
#include "sim/sim_config.h"

namespace echoplan::sim {

class Scene;

// The arm's sensor readings of one action, noise-free: channels j1..j7 (N m) and force_x,
// force_y, force_z (N), one sample per 1/rate_hz s from the action's start (t = 0).
struct ArmReadings {
  signal::Series effort;
  signal::Series force;
};

// Samples the readings during the dynamic part of an action, after each physics step.
class ArmSensorRecorder {
 public:
  ArmSensorRecorder(const Scene& scene, double rate_hz, ArmReadings& readings);

  // After mj_step2 of the step ending `time` s into the action: a sample when `time` has reached
  // the next sample's time.
  void after_step(const mjModel* m, const mjData* d, double time);
  // For an action that failed before it moved: one reading at t = 0 of the arm holding its pose
  // (each joint carries its gravity torque) with the hand open.
  void at_rest(const mjData* d);

 private:
  const Scene& s_;
  double period_;
  ArmReadings& readings_;
  int next_ = 0;  // index of the next sample
};

// Adds independent Gaussian noise of `sensors.effort_noise_nm` and `sensors.force_noise_n`
// (standard deviations) to every sample, drawn from `rng`.
void add_sensor_noise(ArmReadings& readings, const SensorConfig& sensors, Rng& rng);

}  // namespace echoplan::sim
