// The simulated robot: executes the two sound-making actions on one object in the MuJoCo scene and
// reports what happened, including the object-table contacts the sound synthesis needs.
//
// Actions (sim/sound_action.h):
//   slide  - the fingertip pad pushes the object 5 cm along +x at the action's push speed;
//   strike - the hand closes on the object (a compliant grasp), lifts it 5 cm, brings it down at
//            the action's impact speed onto the table, levels it and holds it while the contact
//            settles, then opens: one impact.
//
// A trial is a sequence of actions on one object: reset_trial() puts the arm in the original
// system's initial configuration and the object at its nominal place (plus the trial's placement
// and orientation); every execute() then continues from the state the previous action left (the
// object where it ended, the arm where it stopped). The move from the arm's current pose to the
// object is silent and kinematic (checked for arm-table contact at waypoints); the action proper is
// simulated dynamically and its time starts at 0. Physical outcomes (the arm hits the table, the
// object has been pushed out of reach or has fallen over) are reported in the outcome, never
// thrown.
//
// The MuJoCo models are never written: the grasp is a spring-damper applied through mjData, and the
// pad's contact with the object is chosen by stepping the compiled model variant the action needs.
#pragma once

#include <array>
#include <memory>
#include <string>

#include "common/rng.h"
#include "sim/action_status.h"
#include "sim/arm_sensors.h"
#include "sim/catalogue.h"
#include "sim/contact_trace.h"
#include "sim/sim_config.h"
#include "sim/sound_action.h"

namespace echoplan::sim {

class Scene;

struct ActionOutcome {
  SoundAction action = SoundAction::slide;
  ActionStatus status = ActionStatus::done;
  std::string reason;           // for collision and failed: what happened, in words
  double collision_time_s = 0;  // s from the start of the action (negative: during the approach)
  double duration_s = 0;  // s simulated, from the start of the action to its end (or the collision)
  ObjectPlacement
      placement;  // where the trial put the object (the same for every action of a trial)
  ActionVariation variation;             // what was drawn for this action
  std::array<double, 3> object_start{};  // m, world: the object's base centre when the action began
  std::array<double, 3>
      object_displacement{};  // m, world frame: where the object ended minus where it began
  ContactTrace trace;         // object-table contacts
  ArmReadings readings;  // the arm's joint torques and wrist force, noise-free (no samples when the
                         // action failed before it began)

  bool collision() const { return status == ActionStatus::collision; }
};

class SimulatedRobot {
 public:
  // Builds the scene for `object` (compiling the MuJoCo model once). The catalogue and config are
  // copied. No trial has begun: the first execute() begins one (drawing its placement from its
  // rng).
  // On the first of the config's tables (the catalogue's default when it names none).
  SimulatedRobot(const Catalogue& catalogue, const std::string& object, const SimConfig& config);
  // On `table`.
  SimulatedRobot(const Catalogue& catalogue, const std::string& object, const SimConfig& config,
                 const TableSpec& table);
  ~SimulatedRobot();
  SimulatedRobot(const SimulatedRobot&) = delete;
  SimulatedRobot& operator=(const SimulatedRobot&) = delete;

  // Begins a trial: arm in the initial configuration, grasp open, object at rest at its nominal
  // place moved by `placement`. Drawing it from `rng` consumes sample_placement's draws.
  void reset_trial(const ObjectPlacement& placement);
  void reset_trial(Rng& rng);

  // Runs `action` from the current state, drawing the action's variation from `rng` (and, if no
  // trial has begun, the trial's placement first).
  ActionOutcome execute(SoundAction action, Rng& rng);

  // As execute(), with the action's variation given instead of drawn (a trial must have begun, or
  // one with the nominal placement is begun).
  ActionOutcome execute(SoundAction action, const ActionVariation& variation);

  // The object's base centre (m, world) and whether a trial is under way.
  std::array<double, 3> object_position() const;
  bool trial_begun() const { return trial_begun_; }
  const ObjectPlacement& placement() const { return placement_; }

  const ObjectSpec& object() const { return object_; }
  const TableSpec& table() const { return table_; }
  const SimConfig& config() const { return config_; }
  // The MuJoCo scene (for inspection and tests; its models are never written).
  const Scene& scene() const;

 private:
  ObjectSpec object_;
  TableSpec table_;
  SimConfig config_;
  std::unique_ptr<Scene> scene_;
  bool trial_begun_ = false;
  ObjectPlacement placement_;
  std::array<double, 7>
      joint_targets_{};  // rad, the arm's servo targets where the last action left them
};

}  // namespace echoplan::sim
