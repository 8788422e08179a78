#include "sim/approach.h"

#include "sim/cartesian_motion.h"
#include "sim/contact_recorder.h"

namespace echoplan::sim {

namespace {

constexpr double kReachTolerance =
    0.005;  // m: an IK solution further than this from its target is out of reach
// Waypoints along the line, and DLS iterations per waypoint (four times as many at the last, so
// the action starts where it should).
constexpr int kWaypoints = 10, kIterations = 8;

}  // namespace

Eigen::Quaterniond upright_hand(const Scene& s, const mjModel* m, const mjData* d, mjData* kin) {
  std::array<double, kArmJoints> initial = kInitialArmConfiguration;
  mju_copy(kin->qpos, d->qpos, m->nq);  // every field it is read for is recomputed from qpos
  for (int i = 0; i < kArmJoints; ++i) kin->qpos[i] = initial[i];
  mj_kinematics(m, kin);
  return site_orientation(kin, s.end_effector_site);
}

ApproachResult approach(const Scene& s, const mjModel* m, const mjData* d, mjData* kin,
                        std::array<double, kArmJoints>& q, const Eigen::Vector3d& target,
                        const Eigen::Quaterniond& upright) {
  for (int i = 0; i < kArmJoints; ++i) kin->qpos[i] = q[i];
  mj_kinematics(m, kin);
  const Eigen::Vector3d start_pos = site_position(kin, s.end_effector_site);
  const Eigen::Quaterniond start_rot = site_orientation(kin, s.end_effector_site);
  for (int w = 1; w <= kWaypoints; ++w) {
    const double f = static_cast<double>(w) / kWaypoints;
    const Eigen::Vector3d waypoint = start_pos + (target - start_pos) * f;
    const Eigen::Quaterniond turn = start_rot.slerp(f, upright);
    for (int it = 0; it < (w == kWaypoints ? 4 * kIterations : kIterations); ++it)
      dls_step(m, kin, s.end_effector_site, q.data(), waypoint, turn);
    mju_copy(kin->qpos, d->qpos, m->nq);
    for (int i = 0; i < kArmJoints; ++i) kin->qpos[i] = q[i];
    mj_fwdPosition(m, kin);
    if (arm_touches_table(kin, s)) return ApproachResult::meets_table;
  }
  if ((site_position(kin, s.end_effector_site) - target).norm() > kReachTolerance)
    return ApproachResult::out_of_reach;
  return ApproachResult::reached;
}

}  // namespace echoplan::sim
