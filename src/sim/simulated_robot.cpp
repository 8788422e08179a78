#include "sim/simulated_robot.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <vector>

#include "common/error.h"
#include "sim/arm_kinematics.h"
#include "sim/scene.h"

namespace echoplan::sim {

namespace {

constexpr double kActionDistance = 0.05;    // m: the slide's push and the strike's lift (seed section 3.2.1)
constexpr double kLiftSpeed = 0.10;         // m/s
constexpr double kPressDepth = 0.001;       // m the strike's target lies below the resting height
constexpr double kPadGap = 0.001;           // m between pad and object before the push
constexpr double kPreSettleTime = 0.04;     // s simulated before the action so the object rests
constexpr double kSettleTime = 0.2;         // s simulated after the motion so the object comes to rest
constexpr double kImpactSpeedThreshold = 0.02;  // m/s: slower approaches (resting, rocking while pushed) are heard through friction
constexpr double kImpactRefractory = 0.010;      // s: a soft contact settles over a few steps; one impact
constexpr double kDampedLeastSquaresLambda = 0.02;
constexpr double kPostureGain = 0.1;        // per IK step, towards the initial joint configuration
constexpr double kControlPeriod = 0.01;     // s between IK solutions (100 Hz, as the arm's own controller)

using Vector6 = Eigen::Matrix<double, 6, 1>;

// A straight-line end-effector motion at constant speed, with the orientation turning uniformly.
struct Segment {
  double duration_s;
  Eigen::Vector3d from, to;
  Eigen::Quaterniond turn_from, turn_to;
  enum class Event { none, grasp, release } at_start = Event::none;
};

Eigen::Quaterniond site_orientation(const mjData* d, int site) {
  Eigen::Matrix3d r;
  for (int i = 0; i < 9; ++i) r(i / 3, i % 3) = d->site_xmat[9 * site + i];
  return Eigen::Quaterniond(r);
}

Eigen::Vector3d site_position(const mjData* d, int site) {
  return {d->site_xpos[3 * site], d->site_xpos[3 * site + 1], d->site_xpos[3 * site + 2]};
}

// One damped-least-squares step that moves the joint targets `q` so the end-effector site (computed
// kinematically in `kin`) approaches the desired pose: dq = J^T (J J^T + lambda^2 I)^-1 e, plus a pull
// towards the initial posture in the Jacobian's null space, so the redundant seventh joint keeps the
// elbow up instead of drifting towards the table.
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
      jac * jac.transpose() + kDampedLeastSquaresLambda * kDampedLeastSquaresLambda * Eigen::Matrix<double, 6, 6>::Identity();
  const auto solver = jjt.ldlt();
  Eigen::Matrix<double, kArmJoints, 1> posture;
  for (int i = 0; i < kArmJoints; ++i) posture[i] = kPostureGain * (kInitialArmConfiguration[i] - q[i]);
  const Eigen::Matrix<double, kArmJoints, 1> null_space = posture - jac.transpose() * solver.solve(jac * posture);
  const Eigen::Matrix<double, kArmJoints, 1> dq = jac.transpose() * solver.solve(error) + null_space;
  for (int i = 0; i < kArmJoints; ++i) q[i] += dq[i];
}

// Effective mass of the object at a contact along `normal`: 1 / (j M^-1 j^T) with j the normal row
// of the contact point's Jacobian over the object's own six degrees of freedom. The grasp is
// compliant on the ~0.1 ms scale of an impact, so the arm does not take part.
double effective_mass(const mjModel* m, mjData* d, const Scene& s, const mjtNum point[3], const Eigen::Vector3d& normal) {
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

// Collects the ContactTrace during the dynamic part of an action.
class ContactRecorder {
 public:
  ContactRecorder(const Scene& scene, ContactTrace& trace) : s_(scene), trace_(trace) {}

  // After mj_step1: contacts and pre-impulse velocities of this step.
  void before_forces(const mjModel* m, mjData* d, double time) {
    object_contacts_.clear();
    arm_on_table_ = false;
    best_speed_ = 0;
    best_contact_ = -1;
    mjtNum velocity[6];
    mj_objectVelocity(m, d, mjOBJ_BODY, s_.object_body, velocity, 0);
    const Eigen::Vector3d omega(velocity[0], velocity[1], velocity[2]);
    const Eigen::Vector3d linear(velocity[3], velocity[4], velocity[5]);
    const Eigen::Vector3d origin(d->xpos + 3 * s_.object_body);
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
    if (best_speed_ > kImpactSpeedThreshold && time - last_impact_ > kImpactRefractory) {
      Impact impact;
      impact.time_s = time;
      impact.normal_speed = best_speed_;
      impact.effective_mass = effective_mass(m, d, s_, d->contact[best_contact_].pos, best_normal_);
      trace_.impacts.push_back(impact);
      pending_impact_ = true;
      last_impact_ = time;
    }
  }

  // After mj_step2: contact forces of this step, and the object's sliding speed.
  void after_forces(const mjModel* m, mjData* d) {
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
    trace_.normal_force.push_back(total);
    trace_.sliding_speed.push_back(total > 0 ? std::hypot(v[0], v[1]) : 0.0);
    ++trace_.steps;
  }

  bool arm_on_table() const { return arm_on_table_; }

 private:
  const Scene& s_;
  ContactTrace& trace_;
  std::vector<int> object_contacts_;
  bool arm_on_table_ = false;
  bool pending_impact_ = false;
  double best_speed_ = 0;
  int best_contact_ = -1;
  Eigen::Vector3d best_normal_ = Eigen::Vector3d::UnitZ();
  double last_impact_ = -1.0;
};

bool arm_touches_table(const mjData* d, const Scene& s) {
  for (int i = 0; i < d->ncon; ++i) {
    const mjContact& c = d->contact[i];
    if ((c.geom1 == s.table_geom && s.is_arm_geom(c.geom2)) || (c.geom2 == s.table_geom && s.is_arm_geom(c.geom1)))
      return true;
  }
  return false;
}

// Sets the weld's reference to the object's current pose relative to the hand, so switching it on
// holds the object where it is (MuJoCo 2.2 weld data: anchor[3], relpose[7], torquescale).
void hold_current_pose(mjModel* m, const mjData* d, const Scene& s) {
  const int hand = s.hand_body, object = s.object_body;
  mjtNum hand_inverse_pos[3], hand_inverse_quat[4], rel_pos[3], rel_quat[4];
  mju_negPose(hand_inverse_pos, hand_inverse_quat, d->xpos + 3 * hand, d->xquat + 4 * hand);
  mju_mulPose(rel_pos, rel_quat, hand_inverse_pos, hand_inverse_quat, d->xpos + 3 * object, d->xquat + 4 * object);
  mjtNum* data = m->eq_data + mjNEQDATA * s.grasp_weld;
  mju_zero3(data);
  mju_copy3(data + 3, rel_pos);
  mju_copy4(data + 6, rel_quat);
  data[10] = 1.0;
}

}  // namespace

SimulatedRobot::SimulatedRobot(const Catalogue& catalogue, const std::string& object, const SimConfig& config)
    : object_(catalogue.object(object)),
      table_(catalogue.table),
      config_(config),
      scene_(std::make_unique<Scene>(object_, table_, config.physics)) {}

SimulatedRobot::~SimulatedRobot() = default;

ActionOutcome SimulatedRobot::execute(const std::string& action, Rng& rng) {
  if (action != kSlide && action != kStrike)
    throw InputError("", 0, "unknown action '" + action + "' (known: slide, strike)");
  return execute(action, sample_trial(config_.variability, rng));
}

ActionOutcome SimulatedRobot::execute(const std::string& action, const TrialParameters& p) {
  const bool strike = action == kStrike;
  if (!strike && action != kSlide) throw InputError("", 0, "unknown action '" + action + "' (known: slide, strike)");
  Scene& s = *scene_;
  mjModel* m = s.model();
  mjData* d = s.data();
  ActionOutcome outcome;
  outcome.action = action;
  outcome.parameters = p;
  outcome.trace.timestep_s = m->opt.timestep;

  // Reset: arm in the initial configuration, object at its place, grasp off. The pad may touch the
  // object only when it pushes.
  mj_resetData(m, d);
  m->eq_active[s.grasp_weld] = 0;
  m->geom_conaffinity[s.pad_geom] = strike ? kContactTable : (kContactTable | kContactObject);
  for (int i = 0; i < kArmJoints; ++i) d->qpos[i] = kInitialArmConfiguration[i];
  const Eigen::Vector3d nominal_ee(s.initial_end_effector().data());
  const Eigen::Vector3d object_base(nominal_ee.x() + kObjectOffsetX + p.placement_x, nominal_ee.y() + p.placement_y,
                                    s.table_top_z);
  for (int k = 0; k < 3; ++k) d->qpos[s.object_qpos + k] = object_base[k];
  outcome.trace.object_position = {object_base.x(), object_base.y(), object_base.z()};
  mj_forward(m, d);
  const Eigen::Quaterniond start_rot = site_orientation(d, s.end_effector_site);
  const Eigen::Vector3d start_pos = site_position(d, s.end_effector_site);

  // Where the action begins: for a strike the hand around the object's axis at grasp height, for a
  // slide the pad just behind the object.
  const double ee_z = s.table_top_z + p.grasp_height;
  const Eigen::Vector3d at_object =
      strike ? Eigen::Vector3d(object_base.x(), object_base.y(), ee_z)
             : Eigen::Vector3d(object_base.x() - object_.radius - kPadRadius - kPadGap, object_base.y(), ee_z);

  // The silent approach, kinematically: DLS to waypoints along the straight line, checking for the
  // arm meeting the table at each.
  std::vector<double> q(kInitialArmConfiguration.begin(), kInitialArmConfiguration.end());
  auto kin = std::unique_ptr<mjData, void (*)(mjData*)>(mj_makeData(m), mj_deleteData);
  mju_copy(kin->qpos, d->qpos, m->nq);
  constexpr int kWaypoints = 10, kIterations = 8;
  for (int w = 1; w <= kWaypoints; ++w) {
    const Eigen::Vector3d target = start_pos + (at_object - start_pos) * (static_cast<double>(w) / kWaypoints);
    for (int it = 0; it < kIterations; ++it) dls_step(m, kin.get(), s.end_effector_site, q.data(), target, start_rot);
    mju_copy(kin->qpos, d->qpos, m->nq);
    for (int i = 0; i < kArmJoints; ++i) kin->qpos[i] = q[i];
    mj_fwdPosition(m, kin.get());
    if (arm_touches_table(kin.get(), s)) {
      outcome.collision = true;
      outcome.collision_time_s = -1.0;
      return outcome;
    }
  }
  for (int i = 0; i < kArmJoints; ++i) d->qpos[i] = q[i];
  mj_forward(m, d);

  // Let the object settle into its resting contact before the action starts (unrecorded), so the
  // first "impact" is not the object dropping through the contact margin.
  for (int k = 0; k < static_cast<int>(kPreSettleTime / m->opt.timestep); ++k) {
    mj_step1(m, d);
    for (int i = 0; i < kArmJoints; ++i) {
      d->ctrl[i] = q[i];
      d->qfrc_applied[i] = d->qfrc_bias[i];
    }
    mj_step2(m, d);
  }

  // The action as straight-line segments of the end effector.
  std::vector<Segment> plan;
  const Eigen::Vector3d up(0, 0, kActionDistance);
  if (strike) {
    // The tilt turns the object about a horizontal axis through the grasp point while lifting, so
    // it meets the table rim first.
    const double azimuth = p.tilt_azimuth_deg * kPi / 180.0;
    const Eigen::Quaterniond tilted =
        Eigen::Quaterniond(Eigen::AngleAxisd(p.impact_tilt_deg * kPi / 180.0,
                                             Eigen::Vector3d(std::cos(azimuth), std::sin(azimuth), 0.0))) *
        start_rot;
    const Eigen::Vector3d bottom = at_object - Eigen::Vector3d(0, 0, kPressDepth);
    plan.push_back({0.1, at_object, at_object, start_rot, start_rot, Segment::Event::grasp});
    plan.push_back({kActionDistance / kLiftSpeed, at_object, at_object + up, start_rot, tilted});
    plan.push_back({0.1, at_object + up, at_object + up, tilted, tilted});
    plan.push_back({(kActionDistance + kPressDepth) / p.impact_speed, at_object + up, bottom, tilted, tilted});
    plan.push_back({0.1, bottom, bottom, tilted, tilted});
    plan.push_back({kSettleTime, bottom, bottom, tilted, tilted, Segment::Event::release});
  } else {
    const Eigen::Vector3d end = at_object + Eigen::Vector3d(kActionDistance + kPadGap, 0, 0);
    plan.push_back({(kActionDistance + kPadGap) / p.push_speed, at_object, end, start_rot, start_rot});
    plan.push_back({kSettleTime, end, end, start_rot, start_rot});
  }

  // Dynamics: joint servos track targets from DLS on the kinematic copy; gravity and Coriolis forces
  // of the arm are compensated, as the real arm's controller does.
  ContactRecorder recorder(s, outcome.trace);
  const double dt = m->opt.timestep;
  const int control_steps = std::max(1, static_cast<int>(std::lround(kControlPeriod / dt)));
  std::vector<double> q_previous = q;
  double time = 0;
  for (const Segment& seg : plan) {
    if (seg.at_start == Segment::Event::grasp) {
      hold_current_pose(m, d, s);
      m->eq_active[s.grasp_weld] = 1;
    } else if (seg.at_start == Segment::Event::release) {
      m->eq_active[s.grasp_weld] = 0;
    }
    const int steps = std::max(1, static_cast<int>(std::lround(seg.duration_s / dt)));
    int tick_start = 0, tick_length = 1;
    for (int k = 1; k <= steps; ++k) {
      // Each control tick solves IK for the pose at the tick's end; joint targets ramp linearly to it.
      if ((k - 1) % control_steps == 0) {
        q_previous = q;
        tick_start = k - 1;
        tick_length = std::min(control_steps, steps - tick_start);
        const double f = static_cast<double>(tick_start + tick_length) / steps;
        dls_step(m, kin.get(), s.end_effector_site, q.data(), seg.from + (seg.to - seg.from) * f,
                 seg.turn_from.slerp(f, seg.turn_to));
      }
      const double ramp = static_cast<double>(k - tick_start) / tick_length;
      mj_step1(m, d);
      recorder.before_forces(m, d, time);
      for (int i = 0; i < kArmJoints; ++i) {
        d->ctrl[i] = q_previous[i] + ramp * (q[i] - q_previous[i]);
        d->qfrc_applied[i] = d->qfrc_bias[i];
      }
      mj_step2(m, d);
      recorder.after_forces(m, d);
      time += dt;
      if (recorder.arm_on_table()) {
        outcome.collision = true;
        outcome.collision_time_s = time;
        outcome.duration_s = time;
        for (int c = 0; c < 3; ++c) outcome.object_displacement[c] = d->qpos[s.object_qpos + c] - object_base[c];
        return outcome;
      }
    }
  }
  outcome.duration_s = time;
  for (int k = 0; k < 3; ++k) outcome.object_displacement[k] = d->qpos[s.object_qpos + k] - object_base[k];
  return outcome;
}

}  // namespace echoplan::sim
