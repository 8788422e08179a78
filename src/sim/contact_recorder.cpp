#include "sim/contact_recorder.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "sim/scene.h"

namespace echoplan::sim {

namespace {

// What counts as an impact (docs/simulator.md, "What is modelled", contacts to sound; checked in
// "The mug strike: second hit, tilted landing, low frequencies": every strike of every object and
// seed gives one impact, no slide gives any).
constexpr double kImpactSpeedThreshold =
    0.02;  // m/s: slower approaches (resting, rocking while pushed) are heard through friction
constexpr double kImpactRefractory =
    0.010;  // s: a soft contact settles over a few steps; one impact
constexpr double kImpactGap =
    0.0005;  // m: the gap an impact closes (well above the soft contact's chatter)

using Vector6 = Eigen::Matrix<double, 6, 1>;

}  // namespace

double effective_mass(const mjModel* m, const mjData* d, const Scene& s, const mjtNum point[3],
                      const Eigen::Vector3d& normal) {
  std::vector<mjtNum> jacp(3 * m->nv), dense(m->nv * m->nv);
  mj_jac(m, d, jacp.data(), nullptr, point, s.object_body);
  mj_fullM(m, dense.data(), d->qM);
  Eigen::Matrix<double, 6, 6> mass;
  Vector6 row;
  for (int a = 0; a < 6; ++a) {
    row[a] = normal.x() * jacp[s.object_dof + a] + normal.y() * jacp[m->nv + s.object_dof + a] +
             normal.z() * jacp[2 * m->nv + s.object_dof + a];
    for (int b = 0; b < 6; ++b) mass(a, b) = dense[(s.object_dof + a) * m->nv + s.object_dof + b];
  }
  return 1.0 / row.dot(mass.ldlt().solve(row));
}

bool arm_touches_table(const mjData* d, const Scene& s) {
  for (int i = 0; i < d->ncon; ++i) {
    const mjContact& c = d->contact[i];
    if ((c.geom1 == s.table_geom && s.is_arm_geom(c.geom2)) ||
        (c.geom2 == s.table_geom && s.is_arm_geom(c.geom1)))
      return true;
  }
  return false;
}

void ContactRecorder::before_forces(const mjModel* m, mjData* d, double time) {
  object_contacts_.clear();
  arm_on_table_ = false;
  best_speed_ = 0;
  best_contact_ = -1;
  mjtNum velocity[6];
  mj_objectVelocity(m, d, mjOBJ_BODY, s_.object_body, velocity, 0);
  const Eigen::Vector3d omega(velocity[0], velocity[1], velocity[2]);
  const Eigen::Vector3d linear(velocity[3], velocity[4], velocity[5]);
  // mj_objectVelocity's linear part is the velocity of the body's centre of mass.
  const Eigen::Vector3d origin(d->xipos + 3 * s_.object_body);
  for (int i = 0; i < d->ncon; ++i) {
    const mjContact& c = d->contact[i];
    const bool table = c.geom1 == s_.table_geom || c.geom2 == s_.table_geom;
    if (table && (s_.is_arm_geom(c.geom1) || s_.is_arm_geom(c.geom2))) arm_on_table_ = true;
    if (!table || (c.geom1 != s_.object_geom && c.geom2 != s_.object_geom)) continue;
    object_contacts_.push_back(i);
    Eigen::Vector3d normal(c.frame[0], c.frame[1], c.frame[2]);
    if (normal.z() < 0) normal = -normal;  // from the table up into the object
    const Eigen::Vector3d point(c.pos[0], c.pos[1], c.pos[2]);
    const double approach = -(linear + omega.cross(point - origin)).dot(normal);
    if (approach > best_speed_) {
      best_speed_ = approach;
      best_contact_ = i;
      best_normal_ = normal;
    }
  }
  // An impact closes a gap: the object must have been clear of the table (its lowest rim point
  // more than kImpactGap above it) since it last touched. A pushed or rocking object whose soft
  // contact chatters within the contact's compliance is heard through friction, not as hits.
  const double axis_z = d->xmat[9 * s_.object_body + 8];
  const double lowest = d->xpos[3 * s_.object_body + 2] -
                        object_radius_ * std::sqrt(std::max(0.0, 1 - axis_z * axis_z));
  if (lowest - s_.table_top_z > kImpactGap) clear_of_table_ = true;
  if (clear_of_table_ && best_speed_ > kImpactSpeedThreshold &&
      time - last_impact_ > kImpactRefractory) {
    Impact impact;
    impact.time_s = time;
    impact.normal_speed = best_speed_;
    impact.effective_mass = effective_mass(m, d, s_, d->contact[best_contact_].pos, best_normal_);
    trace_.impacts.push_back(impact);
    pending_impact_ = true;
    last_impact_ = time;
    clear_of_table_ = false;
  }
}

void ContactRecorder::after_forces(const mjModel* m, mjData* d) {
  double total = 0;
  const Eigen::Vector3d origin(d->xpos + 3 * s_.object_body);
  Eigen::Matrix3d rot;
  for (int k = 0; k < 9; ++k) rot(k / 3, k % 3) = d->xmat[9 * s_.object_body + k];
  std::vector<RimContact> rim;
  for (int i : object_contacts_) {
    mjtNum force[6];
    mj_contactForce(m, d, i, force);
    const double normal_force = std::max(0.0, force[0]);
    total += normal_force;
    const Eigen::Vector3d local = rot.transpose() * (Eigen::Vector3d(d->contact[i].pos) - origin);
    rim.push_back({std::atan2(local.y(), local.x()), normal_force});
  }
  if (pending_impact_) {
    trace_.impacts.back().contacts = std::move(rim);
    pending_impact_ = false;
  }
  const double* v = d->qvel + s_.object_dof;
  if (total > 0 && !pending_impact_) clear_of_table_ = false;
  trace_.normal_force.push_back(total);
  double joints = 0;
  for (int i = 0; i < kArmJoints; ++i) joints += std::abs(d->qvel[i]);
  trace_.joint_speed.push_back(joints);
  trace_.sliding_speed.push_back(total > 0 ? std::hypot(v[0], v[1]) : 0.0);
  ++trace_.steps;
}

}  // namespace echoplan::sim
