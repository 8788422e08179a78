// The gripper's hold on the object: a compliant spring-damper between hand and object applied
// through mjData::xfrc_applied, so the MuJoCo model is never written to attach or release it.
#pragma once

#include <mujoco/mujoco.h>

#include <Eigen/Geometry>

namespace echoplan::sim {

class Scene;

// The grasp: a spring-damper pulling the object towards the pose it had in the hand when the
// fingers closed, applied as equal and opposite forces on object and hand through
// mjData::xfrc_applied, with the object's weight carried. Its strength ramps as the fingers close
// and open, so neither makes a jolt; being compliant, it lets the object meet the table on its own
// effective mass.
class CompliantGrasp {
 public:
  explicit CompliantGrasp(const Scene& s) : s_(s) {}

  // Takes the object's current pose relative to the hand as the held pose.
  void close(const mjData* d);

  // Writes this step's grasp forces (after mj_step1, so poses and velocities are current);
  // `strength` 0 (open) to 1 (closed) ramps the spring as the fingers close and open.
  void apply(const mjModel* m, mjData* d, double strength) const;

 private:
  const Scene& s_;
  Eigen::Vector3d held_position_ = Eigen::Vector3d::Zero();
  Eigen::Quaterniond held_rotation_ = Eigen::Quaterniond::Identity();
};

}  // namespace echoplan::sim
