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

constexpr double kActionDistance =
    0.05;  // m: the slide's push and the strike's lift (seed section 3.2.1)
constexpr double kLiftSpeed = 0.10;      // m/s
constexpr double kPressDepth = 0.001;    // m the strike's target lies below the resting height
constexpr double kPadGap = 0.001;        // m between pad and object before the push
constexpr double kPreSettleTime = 0.04;  // s simulated before the action so the object rests
constexpr double kSettleTime = 0.2;      // s simulated after the motion so the object comes to rest
constexpr double kImpactSpeedThreshold =
    0.02;  // m/s: slower approaches (resting, rocking while pushed) are heard through friction
constexpr double kImpactRefractory =
    0.010;  // s: a soft contact settles over a few steps; one impact
constexpr double kImpactGap =
    0.0005;  // m: the gap an impact closes (well above the soft contact's chatter)
constexpr double kDampedLeastSquaresLambda = 0.02;
constexpr double kPostureGain = 0.1;  // per IK step, towards the initial joint configuration
constexpr double kControlPeriod =
    0.01;                           // s between IK solutions (100 Hz, as the arm's own controller)
constexpr double kGraspTime = 0.1;  // s for the fingers to close
constexpr double kLevelTime =
    0.3;  // s to turn a tilted object upright on the table (slowly: no second hit)
constexpr double kHoldTime = 0.1;      // s the object is held on the table before the hand opens
constexpr double kReleaseTime = 0.05;  // s for the fingers to open
constexpr double kPauseTime = 0.1;     // s at the top of the lift
constexpr double kEaseTime = 0.15;     // s the arm takes to reach its speed from rest and back
// The grasp as a spring-damper between hand and object: natural frequency (rad/s) for the object's
// own mass and inertia, critically damped. 150 rad/s (24 Hz) is as stiff as a gripper's fingers
// hold a light object and keeps the explicit force stable at the 2-5 ms physics steps (omega dt <
// 1).
constexpr double kGraspOmega = 150.0;
constexpr double kReachTolerance =
    0.005;  // m: an IK solution further than this from its target is out of reach
constexpr double kTrackTolerance =
    0.01;  // m: the arm this far from a segment's end has not followed the path
constexpr double kFallenCosine =
    0.7;  // the object's axis more than ~45 degrees from vertical: fallen over

using Vector6 = Eigen::Matrix<double, 6, 1>;

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

  // The share of the path covered at time t in [0, duration_s].
  double progress(double t) const {
    const double ta = std::min(ease_in_s, duration_s / 2),
                 td = std::min(ease_out_s, duration_s / 2);
    const double cruise =
        1.0 / (duration_s - ta / 2 - td / 2);  // path shares per second at full speed
    if (t < ta) return 0.5 * cruise * t * t / ta;
    if (t > duration_s - td) return 1.0 - 0.5 * cruise * (duration_s - t) * (duration_s - t) / td;
    return cruise * (t - ta / 2);
  }
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
// kinematically in `kin`) approaches the desired pose: dq = J^T (J J^T + lambda^2 I)^-1 e, plus a
// pull towards the initial posture in the Jacobian's null space, so the redundant seventh joint
// keeps the elbow up instead of drifting towards the table.
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

// Effective mass of the object at a contact along `normal`: 1 / (j M^-1 j^T) with j the normal row
// of the contact point's Jacobian over the object's own six degrees of freedom. The grasp is
// compliant on the ~0.1 ms scale of an impact, so the arm does not take part.
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

// Collects the ContactTrace during the dynamic part of an action.
class ContactRecorder {
 public:
  ContactRecorder(const Scene& scene, double object_radius, ContactTrace& trace)
      : s_(scene), object_radius_(object_radius), trace_(trace) {}

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
    if (total > 0 && !pending_impact_) clear_of_table_ = false;
    trace_.normal_force.push_back(total);
    trace_.sliding_speed.push_back(total > 0 ? std::hypot(v[0], v[1]) : 0.0);
    ++trace_.steps;
  }

  bool arm_on_table() const { return arm_on_table_; }

 private:
  const Scene& s_;
  double object_radius_;
  ContactTrace& trace_;
  bool clear_of_table_ = false;
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
    if ((c.geom1 == s.table_geom && s.is_arm_geom(c.geom2)) ||
        (c.geom2 == s.table_geom && s.is_arm_geom(c.geom1)))
      return true;
  }
  return false;
}

// The grasp: a spring-damper pulling the object towards the pose it had in the hand when the
// fingers closed, applied as equal and opposite forces on object and hand through
// mjData::xfrc_applied, with the object's weight carried. Its strength ramps as the fingers close
// and open, so neither makes a jolt; being compliant, it lets the object meet the table on its own
// effective mass.
class CompliantGrasp {
 public:
  explicit CompliantGrasp(const Scene& s) : s_(s) {}

  // Takes the object's current pose relative to the hand as the held pose.
  void close(const mjData* d) {
    const Eigen::Matrix3d hand_rot = rotation(d->xmat + 9 * s_.hand_body);
    held_position_ = hand_rot.transpose() *
                     (vec(d->xipos + 3 * s_.object_body) - vec(d->xpos + 3 * s_.hand_body));
    held_rotation_ =
        quat(d->xquat + 4 * s_.hand_body).conjugate() * quat(d->xquat + 4 * s_.object_body);
  }

  // Writes this step's grasp forces (after mj_step1, so poses and velocities are current).
  void apply(const mjModel* m, mjData* d, double strength) const {
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

 private:
  static Eigen::Vector3d vec(const mjtNum* v) { return {v[0], v[1], v[2]}; }
  static Eigen::Quaterniond quat(const mjtNum* q) {
    return Eigen::Quaterniond(q[0], q[1], q[2], q[3]);
  }
  static Eigen::Matrix3d rotation(const mjtNum* r) {
    Eigen::Matrix3d m;
    for (int i = 0; i < 9; ++i) m(i / 3, i % 3) = r[i];
    return m;
  }
  const Scene& s_;
  Eigen::Vector3d held_position_ = Eigen::Vector3d::Zero();
  Eigen::Quaterniond held_rotation_ = Eigen::Quaterniond::Identity();
};

// One physics step with the arm's servos at `targets`, gravity and Coriolis forces of the arm
// compensated as the real arm's controller does. `between` runs after mj_step1 (contacts found,
// forces not yet), `after` after mj_step2.
template <typename Between, typename After>
void physics_step(const mjModel* m, mjData* d, const double* targets, Between&& between,
                  After&& after) {
  mj_step1(m, d);
  between();
  for (int i = 0; i < kArmJoints; ++i) {
    d->ctrl[i] = targets[i];
    d->qfrc_applied[i] = d->qfrc_bias[i];
  }
  mj_step2(m, d);
  after();
}

}  // namespace

const char* to_string(ActionStatus status) {
  switch (status) {
    case ActionStatus::done:
      return "done";
    case ActionStatus::collision:
      return "collision";
    case ActionStatus::failed:
      return "failed";
  }
  return "?";
}

SimulatedRobot::SimulatedRobot(const Catalogue& catalogue, const std::string& object,
                               const SimConfig& config)
    : object_(catalogue.object(object)),
      table_(catalogue.table),
      config_(config),
      scene_(std::make_unique<Scene>(object_, table_, config.physics)) {}

SimulatedRobot::~SimulatedRobot() = default;

const Scene& SimulatedRobot::scene() const { return *scene_; }

void SimulatedRobot::reset_trial(Rng& rng) { reset_trial(sample_setup(config_.variability, rng)); }

void SimulatedRobot::reset_trial(const TrialSetup& setup) {
  Scene& s = *scene_;
  const mjModel* m = s.model();
  mjData* d = s.data();
  mj_resetData(m, d);
  for (int i = 0; i < kArmJoints; ++i) d->qpos[i] = joint_targets_[i] = kInitialArmConfiguration[i];
  const Eigen::Vector3d nominal_ee(s.initial_end_effector().data());
  d->qpos[s.object_qpos + 0] = nominal_ee.x() + kObjectOffsetX + setup.placement_x;
  d->qpos[s.object_qpos + 1] = nominal_ee.y() + setup.placement_y;
  d->qpos[s.object_qpos + 2] = s.table_top_z;
  const double half_turn = setup.orientation_deg * kPi / 360.0;
  d->qpos[s.object_qpos + 3] = std::cos(half_turn);
  d->qpos[s.object_qpos + 4] = d->qpos[s.object_qpos + 5] = 0;
  d->qpos[s.object_qpos + 6] = std::sin(half_turn);
  mj_forward(m, d);
  setup_ = setup;
  trial_begun_ = true;
}

std::array<double, 3> SimulatedRobot::object_position() const {
  const mjData* d = scene_->data();
  const int a = scene_->object_qpos;
  return {d->qpos[a], d->qpos[a + 1], d->qpos[a + 2]};
}

ActionOutcome SimulatedRobot::execute(const std::string& action, Rng& rng) {
  if (action != kSlide && action != kStrike)
    throw InputError("", 0, "unknown action '" + action + "' (known: slide, strike)");
  if (!trial_begun_) reset_trial(rng);
  return execute(action, sample_action(config_.variability, rng));
}

ActionOutcome SimulatedRobot::execute(const std::string& action, const ActionVariation& p) {
  const bool strike = action == kStrike;
  if (!strike && action != kSlide)
    throw InputError("", 0, "unknown action '" + action + "' (known: slide, strike)");
  if (!trial_begun_) reset_trial(TrialSetup{});
  Scene& s = *scene_;
  const mjModel* m = s.model(strike ? PadContact::clear_of_object : PadContact::pushes_object);
  mjData* d = s.data();
  ActionOutcome outcome;
  outcome.action = action;
  outcome.setup = setup_;
  outcome.variation = p;
  outcome.trace.timestep_s = m->opt.timestep;
  mju_zero(d->xfrc_applied, 6 * m->nbody);  // the hand is open between actions
  mj_forward(m, d);
  const Eigen::Vector3d object_base(d->qpos + s.object_qpos);
  outcome.object_start = {object_base.x(), object_base.y(), object_base.z()};
  outcome.trace.object_position = outcome.object_start;
  auto fail = [&](ActionStatus status, const std::string& reason) {
    outcome.status = status;
    outcome.reason = reason;
    return outcome;
  };
  if (d->xmat[9 * s.object_body + 8] < kFallenCosine)
    return fail(ActionStatus::failed, "the object has fallen over");

  // The initial configuration's hand orientation: every action is done with it.
  std::array<double, kArmJoints> initial = kInitialArmConfiguration;
  auto kin = std::unique_ptr<mjData, void (*)(mjData*)>(mj_makeData(m), mj_deleteData);
  mju_copy(kin->qpos, d->qpos, m->nq);
  for (int i = 0; i < kArmJoints; ++i) kin->qpos[i] = initial[i];
  mj_kinematics(m, kin.get());
  const Eigen::Quaterniond upright = site_orientation(kin.get(), s.end_effector_site);
  std::array<double, kArmJoints> q = joint_targets_;
  for (int i = 0; i < kArmJoints; ++i) kin->qpos[i] = q[i];
  mj_kinematics(m, kin.get());
  const Eigen::Vector3d start_pos = site_position(kin.get(), s.end_effector_site);
  const Eigen::Quaterniond start_rot = site_orientation(kin.get(), s.end_effector_site);

  // Where the action begins: for a strike the hand around the object's axis (off by the grasp
  // offset) at grasp height, for a slide the pad just behind the object.
  const double ee_z = s.table_top_z + p.grasp_height;
  const Eigen::Vector3d at_object =
      strike ? Eigen::Vector3d(object_base.x() + p.grasp_offset_x,
                               object_base.y() + p.grasp_offset_y, ee_z)
             : Eigen::Vector3d(object_base.x() - object_.radius - kPadRadius - kPadGap,
                               object_base.y() + p.push_offset, ee_z);

  // The silent approach, kinematically: DLS to waypoints along the straight line, checking for the
  // arm meeting the table at each. The object does not move meanwhile.
  constexpr int kWaypoints = 10, kIterations = 8;
  for (int w = 1; w <= kWaypoints; ++w) {
    const double f = static_cast<double>(w) / kWaypoints;
    const Eigen::Vector3d target = start_pos + (at_object - start_pos) * f;
    const Eigen::Quaterniond turn = start_rot.slerp(f, upright);
    for (int it = 0; it < (w == kWaypoints ? 4 * kIterations : kIterations); ++it)
      dls_step(m, kin.get(), s.end_effector_site, q.data(), target, turn);
    mju_copy(kin->qpos, d->qpos, m->nq);
    for (int i = 0; i < kArmJoints; ++i) kin->qpos[i] = q[i];
    mj_fwdPosition(m, kin.get());
    if (arm_touches_table(kin.get(), s)) {
      outcome.collision_time_s = -1.0;
      return fail(ActionStatus::collision,
                  "the arm would touch the table on its way to the object");
    }
  }
  if ((site_position(kin.get(), s.end_effector_site) - at_object).norm() > kReachTolerance)
    return fail(ActionStatus::failed, "the object is out of the arm's reach");
  joint_targets_ = q;
  for (int i = 0; i < kArmJoints; ++i) {
    d->qpos[i] = q[i];
    d->qvel[i] = 0;
  }
  mj_forward(m, d);

  // Let the object settle into its resting contact before the action starts (unrecorded), so the
  // first "impact" is not the object dropping through the contact margin.
  for (int k = 0; k < static_cast<int>(kPreSettleTime / m->opt.timestep); ++k)
    physics_step(
        m, d, q.data(), [] {}, [] {});

  // The action as straight-line segments of the end effector.
  std::vector<Segment> plan;
  const Eigen::Vector3d up(0, 0, kActionDistance);
  if (strike) {
    // The tilt turns the object about a horizontal axis through the grasp point while lifting, so
    // it meets the table rim first; on the table the hand turns it upright again before opening.
    const double azimuth = p.tilt_azimuth_deg * kPi / 180.0;
    const Eigen::Quaterniond tilted =
        Eigen::Quaterniond(
            Eigen::AngleAxisd(p.impact_tilt_deg * kPi / 180.0,
                              Eigen::Vector3d(std::cos(azimuth), std::sin(azimuth), 0.0))) *
        upright;
    const Eigen::Vector3d bottom = at_object - Eigen::Vector3d(0, 0, kPressDepth);
    plan.push_back({kGraspTime, at_object, at_object, upright, upright, 0, 1});
    Segment lift{
        kActionDistance / kLiftSpeed + kEaseTime, at_object, at_object + up, upright, tilted, 1, 1};
    lift.ease_in_s = lift.ease_out_s = kEaseTime;
    plan.push_back(lift);
    plan.push_back({kPauseTime, at_object + up, at_object + up, tilted, tilted, 1, 1});
    Segment descent{(kActionDistance + kPressDepth) / p.impact_speed + kEaseTime / 2,
                    at_object + up,
                    bottom,
                    tilted,
                    tilted,
                    1,
                    1,
                    true};
    descent.ease_in_s = kEaseTime;
    plan.push_back(descent);
    plan.push_back({kLevelTime, bottom, bottom, tilted, upright, 1, 1});
    plan.push_back({kHoldTime, bottom, bottom, upright, upright, 1, 1});
    plan.push_back({kReleaseTime, bottom, bottom, upright, upright, 1, 0});
    plan.push_back({kSettleTime, bottom, bottom, upright, upright, 0, 0});
  } else {
    const Eigen::Vector3d end = at_object + Eigen::Vector3d(kActionDistance + kPadGap, 0, 0);
    Segment push{(kActionDistance + kPadGap) / p.push_speed + kEaseTime, at_object, end, upright,
                 upright};
    push.ease_in_s = push.ease_out_s = kEaseTime;
    plan.push_back(push);
    plan.push_back({kSettleTime, end, end, upright, upright});
  }

  // Dynamics: joint servos track targets from DLS on the kinematic copy (100 Hz, ramped in
  // between).
  ContactRecorder recorder(s, object_.radius, outcome.trace);
  CompliantGrasp grasp(s);
  const double dt = m->opt.timestep;
  const int control_steps = std::max(1, static_cast<int>(std::lround(kControlPeriod / dt)));
  std::array<double, kArmJoints> q_previous = q, servo{};
  double time = 0;
  bool grasp_closed = false;
  for (std::size_t index = 0; index < plan.size(); ++index) {
    const Segment& seg = plan[index];
    const int steps = std::max(1, static_cast<int>(std::lround(seg.duration_s / dt)));
    int tick_start = 0, tick_length = 1;
    for (int k = 1; k <= steps; ++k) {
      // Each control tick solves IK for the pose at the tick's end; joint targets ramp linearly to
      // it.
      if ((k - 1) % control_steps == 0) {
        q_previous = q;
        tick_start = k - 1;
        tick_length = std::min(control_steps, steps - tick_start);
        const double f = seg.progress(seg.duration_s * (tick_start + tick_length) / steps);
        dls_step(m, kin.get(), s.end_effector_site, q.data(), seg.from + (seg.to - seg.from) * f,
                 seg.turn_from.slerp(f, seg.turn_to));
      }
      const double ramp = static_cast<double>(k - tick_start) / tick_length;
      for (int i = 0; i < kArmJoints; ++i) servo[i] = q_previous[i] + ramp * (q[i] - q_previous[i]);
      const double strength =
          seg.grasp_from + (seg.grasp_to - seg.grasp_from) * static_cast<double>(k) / steps;
      physics_step(
          m, d, servo.data(),
          [&] {
            if (strength > 0 && !grasp_closed) {
              grasp.close(d);
              grasp_closed = true;
            }
            grasp.apply(m, d, strength);
            recorder.before_forces(m, d, time);
          },
          [&] { recorder.after_forces(m, d); });
      time += dt;
      if (seg.stop_on_contact && !outcome.trace.impacts.empty()) {
        const double f = seg.progress(seg.duration_s * k / steps);
        const Eigen::Vector3d stop =
            seg.from + (seg.to - seg.from) * f - Eigen::Vector3d(0, 0, kPressDepth);
        for (std::size_t later = index + 1; later < plan.size(); ++later)
          plan[later].from = plan[later].to = stop;
        q = servo;
        break;
      }
      if (recorder.arm_on_table()) {
        joint_targets_ = servo;
        mju_zero(d->xfrc_applied, 6 * m->nbody);
        outcome.collision_time_s = time;
        outcome.duration_s = time;
        for (int c = 0; c < 3; ++c)
          outcome.object_displacement[c] = d->qpos[s.object_qpos + c] - object_base[c];
        return fail(ActionStatus::collision, "the arm touched the table");
      }
    }
    // At the edge of its workspace the arm cannot follow the path (the IK falls behind its target).
    for (int i = 0; i < kArmJoints; ++i) kin->qpos[i] = q[i];
    mj_kinematics(m, kin.get());
    if (!seg.stop_on_contact &&
        (site_position(kin.get(), s.end_effector_site) - seg.to).norm() > kTrackTolerance) {
      joint_targets_ = q;
      mju_zero(d->xfrc_applied, 6 * m->nbody);
      outcome.duration_s = time;
      for (int c = 0; c < 3; ++c)
        outcome.object_displacement[c] = d->qpos[s.object_qpos + c] - object_base[c];
      return fail(
          ActionStatus::failed,
          "the object is at the edge of the arm's reach: the arm could not follow the path");
    }
  }
  joint_targets_ = q;
  mju_zero(d->xfrc_applied, 6 * m->nbody);
  outcome.duration_s = time;
  for (int k = 0; k < 3; ++k)
    outcome.object_displacement[k] = d->qpos[s.object_qpos + k] - object_base[k];
  return outcome;
}

}  // namespace echoplan::sim
