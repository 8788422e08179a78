// The closed loop's world: the planner's action goes to a Robot, a Recorder listens
// around it, an ObservationService classifies the clip, and the heard label becomes the problem's
// observation symbol. With this environment the trial runner drives the real loop (the report's
// section 4.4, Figure 4.2) exactly as it drives the model's own table with TableWorld.
//
// Per action:
//   sensing: recorder.start -> robot.execute -> recorder.stop -> check the recording
//            -> service.observe -> symbol
//            (a robot without a microphone has no recorder: the service gets an empty clip and
//            observes the performance through the robot's other sensors, e.g. the ROS
//            observation node's feature topic)
//            (a collision or failure ends the trial: observation "none", the collision flag and the
//            problem's collision reward, as ObjectIdentificationModel reports a collision);
//   sorting: robot.execute -> observation "none", the problem's sorting reward for the true object,
//            the trial ends.
// Faults (loop/step_fault.h) are marked on the step rather than thrown: an action that failed
// and that the arm calls safe to repeat (ActionReport::retry_safe) is performed again, recording
// and all, up to kMaxAttempts times; any other failure ends the trial as failed. A recording that
// fails its checks (loop/recording_check.h), a recorder or service whose call failed
// (robot::TransientError), or a class the problem does not know skips the step's observation.
// Rewards come from the problem and the true object (the trial runner draws it and passes it to
// reset()), so a real robot's trials are scored as the model would score them.
//
// Everything that can be checked is checked in the constructor, before any trial: the problem must
// be an object-identification problem, and when the service says what it can report, it must have a
// classifier for every sensing action, report only the problem's symbols ("unknown" needs an
// `unknown` symbol) and be able to report each of them. Each failure is an InputError that says
// what to change.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "loop/recording_check.h"
#include "loop/world.h"
#include "pomdp/object_identification_model.h"
#include "robot/observation_service.h"
#include "robot/recorder.h"
#include "robot/robot.h"

namespace echoplan::loop {

// The three parts of a world, owned by the RobotWorld.
struct RobotParts {
  std::unique_ptr<robot::Robot> robot;
  std::unique_ptr<robot::Recorder> recorder;  // null: the robot has no microphone
  std::unique_ptr<robot::ObservationService> service;
  RecordingChecks checks;  // what every recording must pass before it is heard
};

class RobotWorld final : public World {
 public:
  // Performances of one action when every one fails and the arm says repeating is safe.
  static constexpr int kMaxAttempts = 3;

  // `model` is the problem the planner plans on (an ObjectIdentificationModel). `world_objects`
  // maps a problem object to the object the world holds when it is the truth (e.g. coffee_mug ->
  // coffee_mug_weighted); objects not in the map are themselves. Throws InputError as described
  // above.
  RobotWorld(pomdp::ModelPtr model, RobotParts parts,
             std::map<std::string, std::string> world_objects = {});

  // Begins a trial with the object of `true_state`; the world's own random stream is seeded by one
  // draw from `rng`.
  void reset(const pomdp::State& true_state, Rng& rng) override;
  // Runs the action in the world (see the file comment). `rng` is not used: the world drew its seed
  // in reset(). Throws std::logic_error after the trial ended and for an action index out of range.
  WorldStep execute(int action, Rng& rng) override;

  // The hidden state as far as the world knows it: the trial's truth, with the model's kinematic
  // transition applied after each sensing action (a slide moves the object).
  const pomdp::State& true_state() const { return state_; }
  // The object the world holds in this trial (after world_objects).
  const std::string& world_object() const { return world_object_; }
  const pomdp::ObjectIdentificationModel& model() const { return *problem_; }

 private:
  // Executes `action` (recording around it when `record`), again while it fails and the arm says
  // repeating is safe.
  void perform(RobotStep& acted, const std::string& action, bool record);
  // Classifies the clip of a finished sensing action into `robot` and the planner's observation,
  // or marks the step's fault.
  void hear(RobotStep& acted, const std::string& action, pomdp::Outcome& outcome);
  std::optional<pomdp::Observation> symbol_for(const robot::HeardObservation& heard) const;

  pomdp::ModelPtr model_;
  const pomdp::ObjectIdentificationModel* problem_ = nullptr;
  RobotParts parts_;
  std::map<std::string, std::string> world_objects_;
  std::map<std::string, int> symbol_index_;  // observation symbol -> index
  pomdp::State state_;
  std::string world_object_;
  bool ended_ = true;  // until the first reset()
  int trial_ = -1;     // trials begun on this world (the robot's TrialContext::trial)
};

}  // namespace echoplan::loop
