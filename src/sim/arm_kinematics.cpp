#include "sim/arm_kinematics.h"

namespace echoplan::sim {

namespace {

Eigen::Isometry3d joint_origin(const ArmJoint& j) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.translate(Eigen::Vector3d(j.xyz[0], j.xyz[1], j.xyz[2]));
  t.rotate(Eigen::AngleAxisd(j.rpy[2], Eigen::Vector3d::UnitZ()) *
           Eigen::AngleAxisd(j.rpy[1], Eigen::Vector3d::UnitY()) *
           Eigen::AngleAxisd(j.rpy[0], Eigen::Vector3d::UnitX()));
  return t;
}

}  // namespace

Eigen::Isometry3d end_effector_pose(const std::array<double, 7>& q) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  for (std::size_t i = 0; i < kJaco2Joints.size(); ++i)
    t = t * joint_origin(kJaco2Joints[i]) * Eigen::AngleAxisd(q[i], Eigen::Vector3d::UnitZ());
  return t * joint_origin(kJaco2EndEffector);
}

}  // namespace echoplan::sim
