// A world: where the planner's actions happen. The trial runner resets it with the trial's true
// state and executes one action at a time; each action gives the planner's outcome and, for a world
// with a robot in it, everything the robot, the recorder and the observation service produced.
//
// The worlds (loop/world_spec.h says which one a loop uses):
//   TableWorld  (loop/table_world.h)  the problem's own tables draw each observation (no sound);
//   RobotWorld  (loop/robot_world.h)  a robot acts, a recorder listens, a service classifies: the
//                                     simulator, replayed recordings, a real arm, ROS clients.
#pragma once

#include <optional>
#include <string>

#include "audio/clip.h"
#include "common/rng.h"
#include "loop/step_fault.h"
#include "pomdp/environment.h"
#include "pomdp/model.h"
#include "robot/observation_service.h"
#include "robot/recorder.h"
#include "robot/robot.h"

namespace echoplan::loop {

// What one action produced in a world with a robot in it.
struct RobotStep {
  robot::ActionReport report;  // how the robot said it went (its last attempt)
  int attempts = 1;            // executions: more than one after failures the arm called safe
  bool recorded = false;       // a sensing action: the recorder ran and `clip` holds what it heard
  audio::AudioClip clip;
  robot::CaptureReport capture;  // what the recording lost on the way in (live capture)
  bool classified = false;  // the sensing action was done and `heard` holds the service's answer
  robot::HeardObservation heard;
  double observe_ms = 0;           // wall time from the end of the recording to the observation
  std::optional<StepFault> fault;  // what went wrong in this step, if anything (loop/step_fault.h)

  // The planner may learn from this step: nothing went wrong that skips its observation.
  bool observation_skipped() const {
    return fault && fault->effect == FaultEffect::observation_skipped;
  }
};

// One action's result: what the planner is told, and the robot's part when there is one.
struct WorldStep {
  pomdp::Outcome outcome;
  std::optional<RobotStep> robot;
};

class World {
 public:
  virtual ~World() = default;
  // Begins a trial whose hidden truth is `true_state`; the world's own random stream is drawn from
  // `rng`.
  virtual void reset(const pomdp::State& true_state, Rng& rng) = 0;
  // Executes `action` (an index into the problem's actions).
  virtual WorldStep execute(int action, Rng& rng) = 0;
};

}  // namespace echoplan::loop
