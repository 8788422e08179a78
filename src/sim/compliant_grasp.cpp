#include "sim/compliant_grasp.h"

#include <Eigen/Dense>

#include "sim/scene.h"

namespace echoplan::sim {

namespace {

// The grasp as a spring-damper between hand and object: natural frequency (rad/s) for the object's
// own mass and inertia, critically damped. 150 rad/s (24 Hz) is as stiff as a gripper's fingers
// hold a light object and keeps the explicit force stable at the 2-5 ms physics steps (omega dt <
// 1).
constexpr double kGraspOmega = 150.0;

Eigen::Vector3d vec(const mjtNum* v) { return {v[0], v[1], v[2]}; }
Eigen::Quaterniond quat(const mjtNum* q) { return Eigen::Quaterniond(q[0], q[1], q[2], q[3]); }
Eigen::Matrix3d rotation(const mjtNum* r) {
  Eigen::Matrix3d m;
  for (int i = 0; i < 9; ++i) m(i / 3, i % 3) = r[i];
  return m;
}

}  // namespace

void CompliantGrasp::close(const mjData* d) {
  const Eigen::Matrix3d hand_rot = rotation(d->xmat + 9 * s_.hand_body);
  held_position_ =
      hand_rot.transpose() * (vec(d->xipos + 3 * s_.object_body) - vec(d->xpos + 3 * s_.hand_body));
  held_rotation_ =
      quat(d->xquat + 4 * s_.hand_body).conjugate() * quat(d->xquat + 4 * s_.object_body);
}

void CompliantGrasp::apply(const mjModel* m, mjData* d, double strength) const {
  mjtNum* on_object = d->xfrc_applied + 6 * s_.object_body;
  mjtNum* on_hand = d->xfrc_applied + 6 * s_.hand_body;
  mju_zero(on_object, 6);
  mju_zero(on_hand, 6);
  if (strength <= 0) return;
  const int o = s_.object_body, h = s_.hand_body;
  const Eigen::Vector3d hand_pos = vec(d->xpos + 3 * h), hand_com = vec(d->xipos + 3 * h);
  const Eigen::Matrix3d hand_rot = rotation(d->xmat + 9 * h);
  const Eigen::Vector3d target = hand_pos + hand_rot * held_position_;
  const Eigen::Vector3d object_com = vec(d->xipos + 3 * o);
  mjtNum hv[6], ov[6];
  mj_objectVelocity(m, d, mjOBJ_BODY, h, hv,
                    0);  // [angular, linear at the body's centre of mass]
  mj_objectVelocity(m, d, mjOBJ_BODY, o, ov, 0);
  const Eigen::Vector3d hand_omega = vec(hv), object_omega = vec(ov);
  const Eigen::Vector3d target_velocity = vec(hv + 3) + hand_omega.cross(target - hand_com);
  const double mass = m->body_mass[o];
  const double w = kGraspOmega;
  const Eigen::Vector3d force =
      strength * mass *
      (w * w * (target - object_com) + 2 * w * (target_velocity - vec(ov + 3)) -
       Eigen::Vector3d(m->opt.gravity));
  const Eigen::AngleAxisd turn(quat(d->xquat + 4 * h) * held_rotation_ *
                               quat(d->xquat + 4 * o).conjugate());
  const Eigen::Matrix3d inertial_rot = rotation(d->ximat + 9 * o);
  const Eigen::Matrix3d inertia =
      inertial_rot * vec(m->body_inertia + 3 * o).asDiagonal() * inertial_rot.transpose();
  const Eigen::Vector3d torque =
      strength * inertia *
      (w * w * turn.angle() * turn.axis() + 2 * w * (hand_omega - object_omega));
  const Eigen::Vector3d hand_torque = -torque - (object_com - hand_com).cross(force);
  for (int k = 0; k < 3; ++k) {
    on_object[k] = force[k];
    on_object[3 + k] = torque[k];
    on_hand[k] = -force[k];
    on_hand[3 + k] = hand_torque[k];
  }
}

}  // namespace echoplan::sim
