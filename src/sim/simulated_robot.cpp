#include "sim/simulated_robot.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <vector>

#include "sim/action_dynamics.h"
#include "sim/action_script.h"
#include "sim/approach.h"
#include "sim/arm_kinematics.h"
#include "sim/scene.h"
#include "sim/table_choice.h"

namespace echoplan::sim {

namespace {

constexpr double kFallenCosine =
    0.7;  // the object's axis more than ~45 degrees from vertical: fallen over

}  // namespace

SimulatedRobot::SimulatedRobot(const Catalogue& catalogue, const std::string& object,
                               const SimConfig& config)
    : SimulatedRobot(catalogue, object, config, table_of_recording(catalogue, config, 0)) {}

SimulatedRobot::SimulatedRobot(const Catalogue& catalogue, const std::string& object,
                               const SimConfig& config, const TableSpec& table)
    : object_(catalogue.object(object)),
      table_(table),
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
  if (!trial_begun_) reset_trial(ObjectPlacement{});
  Scene& s = *scene_;
  const mjModel* m = s.model(action == SoundAction::strike ? PadContact::clear_of_object
                                                           : PadContact::pushes_object);
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
  ArmSensorRecorder sensors(s, config_.sensors.rate_hz, outcome.readings);
  auto fail = [&](ActionStatus status, const std::string& reason) {
    sensors.at_rest(d);
    outcome.status = status;
    outcome.reason = reason;
    return outcome;
  };
  if (d->xmat[9 * s.object_body + 8] < kFallenCosine)
    return fail(ActionStatus::failed, "the object has fallen over");

  // The approach: silent and kinematic, ending where the action begins.
  mjData* kin = s.scratch();
  const Eigen::Quaterniond upright = upright_hand(s, m, d, kin);
  const Eigen::Vector3d at_object =
      action_start(action, p, object_base, object_.radius, s.table_top_z);
  std::array<double, kArmJoints> q = joint_targets_;
  switch (approach(s, m, d, kin, q, at_object, upright)) {
    case ApproachResult::reached:
      break;
    case ApproachResult::meets_table:
      outcome.collision_time_s = -1.0;
      return fail(ActionStatus::collision,
                  "the arm would touch the table on its way to the object");
    case ApproachResult::out_of_reach:
      return fail(ActionStatus::failed, "the object is out of the arm's reach");
  }
  joint_targets_ = q;
  for (int i = 0; i < kArmJoints; ++i) {
    d->qpos[i] = q[i];
    d->qvel[i] = 0;
  }
  mj_forward(m, d);
  settle_before_action(m, d, q.data());

  // The action proper, dynamically.
  std::vector<Segment> script = action_script(action, p, at_object, upright, config_.arm);
  const ScriptRun run = run_script(s, m, d, kin, script, q, object_.radius, outcome.trace, sensors);
  joint_targets_ = run.joints;
  mju_zero(d->xfrc_applied, 6 * m->nbody);
  outcome.duration_s = run.time_s;
  for (int k = 0; k < 3; ++k)
    outcome.object_displacement[k] = d->qpos[s.object_qpos + k] - object_base[k];
  switch (run.end) {
    case ScriptRun::End::completed:
      break;
    case ScriptRun::End::arm_on_table:
      outcome.collision_time_s = run.time_s;
      return fail(ActionStatus::collision, "the arm touched the table");
    case ScriptRun::End::lost_track:
      return fail(
          ActionStatus::failed,
          "the object is at the edge of the arm's reach: the arm could not follow the path");
  }
  return outcome;
}

}  // namespace echoplan::sim
