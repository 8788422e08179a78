// The Kinova Jaco2 7-DOF arm (j2s7s300) as published by Kinova: joint origins, limits, link masses,
// and its forward kinematics computed directly from that table.
//
// The MuJoCo scene is generated from the same table; the direct forward kinematics here places the
// table under the end effector before the scene is compiled, and checks the compiled model in
// tests.
#pragma once

#include <Eigen/Geometry>
#include <array>

namespace echoplan::sim {

// One revolute joint: its origin relative to the previous link (xyz in m, roll-pitch-yaw in rad as
// in URDF, i.e. R = Rz(yaw) Ry(pitch) Rx(roll)); it rotates about its own local z.
struct ArmJoint {
  std::array<double, 3> xyz;
  std::array<double, 3> rpy;
  double limit;      // rad, symmetric range +-limit; 0 = continuous
  double link_mass;  // kg, the link this joint moves
};

// Joints 1..7 (DESIGN.md, "Facts the simulator needs"); link masses from Kinova's URDF.
inline constexpr double kPi = 3.14159265358979323846;
inline constexpr std::array<ArmJoint, 7> kJaco2Joints{{
    {{0, 0, 0.15675}, {0, kPi, 0}, 0.0, 0.7477},
    {{0, 0.0016, -0.11875}, {-kPi / 2, 0, kPi}, 2.35, 0.8447},
    {{0, -0.205, 0}, {-kPi / 2, 0, 0}, 0.0, 0.8447},
    {{0, 0, -0.205}, {kPi / 2, 0, kPi}, 2.65, 0.6763},
    {{0, 0.2073, -0.0114}, {-kPi / 2, 0, kPi}, 0.0, 0.463},
    {{0, 0, -0.10375}, {kPi / 2, 0, kPi}, 2.25, 0.463},
    {{0, 0.10375, 0}, {-kPi / 2, 0, kPi}, 0.0, 0.99},
}};
// The end effector, fixed to link 7.
inline constexpr ArmJoint kJaco2EndEffector{{0, 0, -0.16}, {kPi, 0, 0}, 0.0, 0.0};

// Pose of the end effector in the arm's base frame for joint angles `q` (rad).
Eigen::Isometry3d end_effector_pose(const std::array<double, 7>& q);

}  // namespace echoplan::sim
