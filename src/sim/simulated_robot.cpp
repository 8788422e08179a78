#include "sim/simulated_robot.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <vector>

#include "common/error.h"
#include "sim/arm_kinematics.h"
#include "sim/cartesian_motion.h"
#include "sim/compliant_grasp.h"
#include "sim/contact_recorder.h"
#include "sim/scene.h"

namespace echoplan::sim {

namespace {

constexpr double kActionDistance =
    0.05;  // m: the slide's push and the strike's lift (seed section 3.2.1)
constexpr double kLiftSpeed = 0.10;      // m/s
constexpr double kPressDepth = 0.001;    // m the strike's target lies below the resting height
constexpr double kPadGap = 0.001;        // m between pad and object before the push
constexpr double kPreSettleTime = 0.04;  // s simulated before the action so the object rests
constexpr double kSettleTime = 0.2;      // s simulated after the strike so the object comes to rest
// s simulated after the push. The pad slows to rest gently (ArmConfig: over the push's last fifth,
// a few tenths of a m/s^2), and friction (mu g: metres per s^2) would stop an object sliding at a
// few cm/s within 20 ms anyway, so only the contacts settle. (Less physics than the strike's 0.2 s
// pays for the lab's longer push: docs/BENCHMARKS.md, "Simulator", session 8.)
constexpr double kSlideSettleTime = 0.05;
constexpr double kControlPeriod =
    0.01;                           // s between IK solutions (100 Hz, as the arm's own controller)
constexpr double kGraspTime = 0.1;  // s for the fingers to close
constexpr double kLevelTime =
    0.3;  // s to turn a tilted object upright on the table (slowly: no second hit)
constexpr double kHoldTime = 0.1;      // s the object is held on the table before the hand opens
constexpr double kReleaseTime = 0.05;  // s for the fingers to open
constexpr double kPauseTime = 0.1;     // s at the top of the lift
constexpr double kEaseTime = 0.15;     // s the strike's lift and descent take to reach speed
constexpr double kReachTolerance =
    0.005;  // m: an IK solution further than this from its target is out of reach
constexpr double kTrackTolerance =
    0.01;  // m: the arm this far from a segment's end has not followed the path
constexpr double kFallenCosine =
    0.7;  // the object's axis more than ~45 degrees from vertical: fallen over

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

SimulatedRobot::SimulatedRobot(const Catalogue& catalogue, const std::string& object,
                               const SimConfig& config)
    : object_(catalogue.object(object)),
      table_(catalogue.table),
      config_(config),
      scene_(std::make_unique<Scene>(object_, table_, config.physics)) {}

SimulatedRobot::~SimulatedRobot() = default;

const Scene& SimulatedRobot::scene() const { return *scene_; }

void SimulatedRobot::reset_trial(Rng& rng) {
  reset_trial(sample_placement(config_.variability, rng));
}

void SimulatedRobot::reset_trial(const ObjectPlacement& placement) {
  Scene& s = *scene_;
  const mjModel* m = s.model();
  mjData* d = s.data();
  mj_resetData(m, d);
  for (int i = 0; i < kArmJoints; ++i) d->qpos[i] = joint_targets_[i] = kInitialArmConfiguration[i];
  const Eigen::Vector3d nominal_ee(s.initial_end_effector().data());
  d->qpos[s.object_qpos + 0] = nominal_ee.x() + kObjectOffsetX + placement.placement_x;
  d->qpos[s.object_qpos + 1] = nominal_ee.y() + placement.placement_y;
  d->qpos[s.object_qpos + 2] = s.table_top_z;
  const double half_turn = placement.orientation_deg * kPi / 360.0;
  d->qpos[s.object_qpos + 3] = std::cos(half_turn);
  d->qpos[s.object_qpos + 4] = d->qpos[s.object_qpos + 5] = 0;
  d->qpos[s.object_qpos + 6] = std::sin(half_turn);
  mj_forward(m, d);
  placement_ = placement;
  trial_begun_ = true;
}

std::array<double, 3> SimulatedRobot::object_position() const {
  const mjData* d = scene_->data();
  const int a = scene_->object_qpos;
  return {d->qpos[a], d->qpos[a + 1], d->qpos[a + 2]};
}

ActionOutcome SimulatedRobot::execute(SoundAction action, Rng& rng) {
  if (!trial_begun_) reset_trial(rng);
  return execute(action, sample_action(config_.variability, rng));
}

ActionOutcome SimulatedRobot::execute(SoundAction action, const ActionVariation& p) {
  const bool strike = action == SoundAction::strike;
  if (!trial_begun_) reset_trial(ObjectPlacement{});
  Scene& s = *scene_;
  const mjModel* m = s.model(strike ? PadContact::clear_of_object : PadContact::pushes_object);
  mjData* d = s.data();
  ActionOutcome outcome;
  outcome.action = action;
  outcome.placement = placement_;
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
  mjData* kin = s.scratch();  // every field it is read for is recomputed from qpos below
  mju_copy(kin->qpos, d->qpos, m->nq);
  for (int i = 0; i < kArmJoints; ++i) kin->qpos[i] = initial[i];
  mj_kinematics(m, kin);
  const Eigen::Quaterniond upright = site_orientation(kin, s.end_effector_site);
  std::array<double, kArmJoints> q = joint_targets_;
  for (int i = 0; i < kArmJoints; ++i) kin->qpos[i] = q[i];
  mj_kinematics(m, kin);
  const Eigen::Vector3d start_pos = site_position(kin, s.end_effector_site);
  const Eigen::Quaterniond start_rot = site_orientation(kin, s.end_effector_site);

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
      dls_step(m, kin, s.end_effector_site, q.data(), target, turn);
    mju_copy(kin->qpos, d->qpos, m->nq);
    for (int i = 0; i < kArmJoints; ++i) kin->qpos[i] = q[i];
    mj_fwdPosition(m, kin);
    if (arm_touches_table(kin, s)) {
      outcome.collision_time_s = -1.0;
      return fail(ActionStatus::collision,
                  "the arm would touch the table on its way to the object");
    }
  }
  if ((site_position(kin, s.end_effector_site) - at_object).norm() > kReachTolerance)
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
    const double push_distance = kActionDistance + kPadGap;  // the pad first closes its gap
    const Eigen::Vector3d end = at_object + Eigen::Vector3d(push_distance, 0, 0);
    // The push's duration is its distance at the drawn mean speed; the arm's profile is scaled to
    // it, so a slower push also builds up more slowly (ArmConfig).
    const double push_time = push_distance / p.push_speed;
    Segment push{push_time, at_object, end, upright, upright};
    push.ease_in_s = config_.arm.push_accelerate_share * push_time;
    push.ease_out_s = config_.arm.push_decelerate_share * push_time;
    plan.push_back(push);
    plan.push_back({kSlideSettleTime, end, end, upright, upright});
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
        dls_step(m, kin, s.end_effector_site, q.data(), seg.from + (seg.to - seg.from) * f,
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
    mj_kinematics(m, kin);
    if (!seg.stop_on_contact &&
        (site_position(kin, s.end_effector_site) - seg.to).norm() > kTrackTolerance) {
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
