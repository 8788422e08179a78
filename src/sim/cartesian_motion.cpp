#include "sim/cartesian_motion.h"

#include <Eigen/Dense>
#include <vector>

#include "sim/scene.h"

namespace echoplan::sim {

namespace {

constexpr double kDampedLeastSquaresLambda = 0.02;
constexpr double kPostureGain = 0.1;  // per IK step, towards the initial joint configuration

using Vector6 = Eigen::Matrix<double, 6, 1>;

}  // namespace

Eigen::Quaterniond site_orientation(const mjData* d, int site) {
  Eigen::Matrix3d r;
  for (int i = 0; i < 9; ++i) r(i / 3, i % 3) = d->site_xmat[9 * site + i];
  return Eigen::Quaterniond(r);
}

Eigen::Vector3d site_position(const mjData* d, int site) {
  return {d->site_xpos[3 * site], d->site_xpos[3 * site + 1], d->site_xpos[3 * site + 2]};
}

void dls_step(const mjModel* m, mjData* kin, int site, double* q, const Eigen::Vector3d& want_pos,
              const Eigen::Quaterniond& want_rot) {
  for (int i = 0; i < kArmJoints; ++i) kin->qpos[i] = q[i];
  mj_kinematics(m, kin);
  mj_comPos(m, kin);
  thread_local std::vector<mjtNum> jacp, jacr;
  jacp.resize(3 * m->nv);
  jacr.resize(3 * m->nv);
  mj_jacSite(m, kin, jacp.data(), jacr.data(), site);
  Eigen::Matrix<double, 6, kArmJoints> jac;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < kArmJoints; ++c) {
      jac(r, c) = jacp[r * m->nv + c];
      jac(r + 3, c) = jacr[r * m->nv + c];
    }
  Vector6 error;
  error.head<3>() = want_pos - site_position(kin, site);
  const Eigen::AngleAxisd rot_error(want_rot * site_orientation(kin, site).inverse());
  error.tail<3>() = rot_error.angle() * rot_error.axis();
  const Eigen::Matrix<double, 6, 6> jjt =
      jac * jac.transpose() + kDampedLeastSquaresLambda * kDampedLeastSquaresLambda *
                                  Eigen::Matrix<double, 6, 6>::Identity();
  const auto solver = jjt.ldlt();
  Eigen::Matrix<double, kArmJoints, 1> posture;
  for (int i = 0; i < kArmJoints; ++i)
    posture[i] = kPostureGain * (kInitialArmConfiguration[i] - q[i]);
  const Eigen::Matrix<double, kArmJoints, 1> null_space =
      posture - jac.transpose() * solver.solve(jac * posture);
  const Eigen::Matrix<double, kArmJoints, 1> dq =
      jac.transpose() * solver.solve(error) + null_space;
  for (int i = 0; i < kArmJoints; ++i) q[i] += dq[i];
}

}  // namespace echoplan::sim
