// The closed loop as an Environment: the planner's action goes to a Robot, a Recorder listens
// around it, an ObservationService classifies the clip, and the heard label becomes the problem's
// observation symbol. With this environment the trial runner drives the real loop (seed report
// section 4.4, Figure 4.2) exactly as it drives the model's own table with ModelEnvironment.
//
// Per action:
//   sensing: recorder.start -> robot.execute -> recorder.stop -> service.observe -> symbol
//            (a collision or failure ends the trial: observation "none", the collision flag and the
//            problem's collision reward, as ObjectIdentificationModel reports a collision);
//   sorting: robot.execute -> observation "none", the problem's sorting reward for the true object,
//            the trial ends.
// Rewards come from the problem and the true object (the trial runner draws it and passes it to
// reset()), so a real robot's trials are scored as the model would score them.
//
// Everything that can be checked is checked in the constructor, before any trial: the problem must
// be an object-identification problem, and when the service says what it can report, it must have a
// classifier for every sensing action, report only the problem's symbols ("unknown" needs an
// `unknown` symbol) and be able to report each of them. Each failure is an InputError that says
// what to change.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "audio/clip.h"
#include "pomdp/environment.h"
#include "pomdp/object_identification_model.h"
#include "robot/observation_service.h"
#include "robot/recorder.h"
#include "robot/robot.h"

namespace echoplan::experiment {

// What one action in the world produced: what a log of the loop needs.
struct LoopStep {
  int trial = 0;  // trials begun on this environment, 0-based
  int step = 0;   // actions executed in this trial, 0-based
  int action = 0;
  std::string action_name;
  robot::ActionReport report;  // how the robot said it went
  bool recorded = false;       // a sensing action: the recorder ran and `clip` holds what it heard
  audio::AudioClip clip;
  bool classified = false;  // the sensing action was done and `heard` holds the service's answer
  robot::HeardObservation heard;
  pomdp::Observation observation;  // what the planner is told
  std::string observation_name;    // the problem's symbol for it ("none": nothing heard)
  double reward = 0;
  bool terminal = false;
  double observe_ms = 0;  // wall time from the end of the recording to the observation
};

// The three parts of a world, owned by the environment.
struct RobotParts {
  std::unique_ptr<robot::Robot> robot;
  std::unique_ptr<robot::Recorder> recorder;
  std::unique_ptr<robot::ObservationService> service;
};

class RobotEnvironment final : public pomdp::Environment {
 public:
  // `model` is the problem the planner plans on (an ObjectIdentificationModel). `world_objects`
  // maps a problem object to the object the world holds when it is the truth (e.g. coffee_mug ->
  // coffee_mug_weighted); objects not in the map are themselves. Throws InputError as described
  // above.
  RobotEnvironment(pomdp::ModelPtr model, RobotParts parts,
                   std::map<std::string, std::string> world_objects = {});

  // Begins a trial with the object of `true_state`; the world's own random stream is seeded by one
  // draw from `rng`.
  void reset(const pomdp::State& true_state, Rng& rng) override;
  // Runs the action in the world (see the file comment). `rng` is not used: the world drew its seed
  // in reset(). Throws std::logic_error after the trial ended and for an action index out of range.
  pomdp::Outcome execute(int action, Rng& rng) override;
  const pomdp::State& true_state() const override { return state_; }

  // Called after every execute() with what the action produced (the clip, the service's answer, the
  // robot's report). Runs on the thread that called execute().
  void set_step_listener(std::function<void(const LoopStep&)> listener) {
    listener_ = std::move(listener);
  }

  // The object the world holds in this trial (after world_objects).
  const std::string& world_object() const { return world_object_; }
  const pomdp::ObjectIdentificationModel& model() const { return *problem_; }

 private:
  pomdp::Observation symbol_for(const robot::HeardObservation& heard,
                                const std::string& action) const;

  pomdp::ModelPtr model_;
  const pomdp::ObjectIdentificationModel* problem_ = nullptr;
  RobotParts parts_;
  std::map<std::string, std::string> world_objects_;
  std::map<std::string, int> symbol_index_;  // observation symbol -> index
  std::function<void(const LoopStep&)> listener_;
  pomdp::State state_;
  std::string world_object_;
  bool ended_ = true;  // until the first reset()
  int trial_ = -1;
  int step_ = 0;
};

// The object-identification model behind `model`; throws InputError naming the problem when it is
// another kind (the loop needs named objects, sensing and sorting actions).
const pomdp::ObjectIdentificationModel& object_problem(const pomdp::Model& model);

}  // namespace echoplan::experiment
