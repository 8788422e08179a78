// The approach: the silent, kinematic move of the arm from where it is to where an action begins
// (action_start). Damped-least-squares IK to waypoints along the straight line, turning the hand
// upright on the way, with the arm checked against the table at each waypoint. The object does not
// move meanwhile and nothing is recorded.
#pragma once

#include <mujoco/mujoco.h>

#include <Eigen/Geometry>
#include <array>

#include "sim/scene.h"

namespace echoplan::sim {

enum class ApproachResult {
  reached,       // the arm's joints `q` put the end effector at the target
  meets_table,   // the arm would touch the table on its way
  out_of_reach,  // the IK ends further than its tolerance from the target
};

// The hand's orientation in the initial configuration (kInitialArmConfiguration), with which
// every action is done. `kin` is the scene's scratch data: its qpos is set from `d` first.
Eigen::Quaterniond upright_hand(const Scene& s, const mjModel* m, const mjData* d, mjData* kin);

// Moves the joint targets `q` (in: where the arm is; out: where the approach ended) so the end
// effector reaches `target` with the hand `upright`, kinematically in `kin` (whose non-arm
// coordinates are those of `d`, as upright_hand left them).
ApproachResult approach(const Scene& s, const mjModel* m, const mjData* d, mjData* kin,
                        std::array<double, kArmJoints>& q, const Eigen::Vector3d& target,
                        const Eigen::Quaterniond& upright);

}  // namespace echoplan::sim
