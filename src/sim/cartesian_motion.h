// Cartesian motions of the arm's end effector in the MuJoCo scene: straight-line segments with
// trapezoidal speed, and the damped-least-squares inverse kinematics that turns a desired
// end-effector pose into joint targets (the arm's own controller does the same at 100 Hz).
#pragma once

#include <mujoco/mujoco.h>

#include <Eigen/Geometry>
#include <algorithm>

namespace echoplan::sim {

// A straight-line end-effector motion at constant speed, with the orientation turning uniformly and
// the grasp's strength ramping linearly (0 open, 1 closed).
struct Segment {
  double duration_s;
  Eigen::Vector3d from, to;
  Eigen::Quaterniond turn_from, turn_to;
  double grasp_from = 0, grasp_to = 0;
  // The strike's descent: when the object meets the table the arm stops there (its controller stops
  // on contact) and the rest of the plan is moved up to where it stopped.
  bool stop_on_contact = false;
  // Trapezoidal speed: seconds of constant acceleration from rest at the start and of deceleration
  // to rest at the end (the arm's controller never jumps in speed); 0: constant speed throughout.
  double ease_in_s = 0, ease_out_s = 0;

  // The share of the path covered at time t, clamped to [0, duration_s]: callers compute t as
  // duration * k / steps, which rounding can put an ulp past the end (with no ease-out that once
  // divided by zero and sent the arm's joint targets to NaN).
  double progress(double t) const {
    t = std::clamp(t, 0.0, duration_s);
    // Ramps longer together than the segment shrink in proportion (a triangle of speed).
    const double ramps = ease_in_s + ease_out_s;
    const double squeeze = ramps > duration_s ? duration_s / ramps : 1.0;
    const double ta = ease_in_s * squeeze, td = ease_out_s * squeeze;
    const double cruise =
        1.0 / (duration_s - ta / 2 - td / 2);  // path shares per second at full speed
    if (t < ta) return 0.5 * cruise * t * t / ta;
    if (td > 0 && t > duration_s - td)
      return 1.0 - 0.5 * cruise * (duration_s - t) * (duration_s - t) / td;
    return cruise * (t - ta / 2);
  }
};

// The pose of MuJoCo site `site` in `d` (after kinematics).
Eigen::Vector3d site_position(const mjData* d, int site);
Eigen::Quaterniond site_orientation(const mjData* d, int site);

// One damped-least-squares step that moves the joint targets `q` so the end-effector site (computed
// kinematically in `kin`) approaches the desired pose: dq = J^T (J J^T + lambda^2 I)^-1 e, plus a
// pull towards the initial posture in the Jacobian's null space, so the redundant seventh joint
// keeps the elbow up instead of drifting towards the table.
// Only the arm's joints (the first kArmJoints of qpos) are moved; `kin` is a scratch mjData whose
// other coordinates (the object) are left as they are.
void dls_step(const mjModel* m, mjData* kin, int site, double* q, const Eigen::Vector3d& want_pos,
              const Eigen::Quaterniond& want_rot);

}  // namespace echoplan::sim
