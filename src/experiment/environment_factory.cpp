#include "experiment/environment_factory.h"

#include <fmt/format.h>

#include <stdexcept>

#include "common/error.h"
#include "robot/classifier_service.h"
#include "robot/replay_recorder.h"
#include "robot/simulated_world.h"

namespace echoplan::experiment {

namespace {

std::string world_object(const LoopSettings& s, const std::string& object) {
  const auto it = s.world_objects.find(object);
  return it == s.world_objects.end() ? object : it->second;
}

// The parts of one environment. `replay` is the indexed folder, copied so that every environment
// deals its own files.
RobotParts make_parts(const LoopSettings& s, const pomdp::ObjectIdentificationModel& problem,
                      const robot::ReplayRecorder* replay) {
  RobotParts parts;
  parts.service = std::make_unique<robot::ClassifierService>(s.classifier);
  if (s.world.kind == WorldSettings::Kind::simulator) {
    auto world = std::make_shared<robot::SimulatedWorld>(s.world.catalogue, s.world.config,
                                                         problem.data().sorting);
    parts.robot = std::make_unique<robot::SimulatedArm>(world);
    parts.recorder = std::make_unique<robot::SimulatedMicrophone>(world);
  } else {
    parts.robot = std::make_unique<robot::ReplayRobot>(problem.spec().action_names);
    parts.recorder = std::make_unique<robot::ReplayRecorder>(*replay);
  }
  return parts;
}

// The checks of the world that RobotEnvironment cannot make (it only sees the interfaces).
void check_world(const LoopSettings& s, const pomdp::ObjectIdentificationModel& problem,
                 const robot::ReplayRecorder* replay) {
  const pomdp::ObjectProblemData& data = problem.data();
  if (s.world.kind == WorldSettings::Kind::simulator) {
    const robot::SimulatedWorld world(s.world.catalogue, s.world.config, data.sorting);
    for (const auto& act : data.sensing) {
      try {
        world.check_action(act.name);
      } catch (const InputError& e) {
        throw InputError(
            fmt::format("problem '{}': sensing action '{}': {}", data.name, act.name, e.what()));
      }
    }
    for (const std::string& object : data.objects) {
      try {
        world.check_object(world_object(s, object));
      } catch (const InputError& e) {
        throw InputError(
            fmt::format("problem '{}' has object '{}', which the simulator cannot hold: {}",
                        data.name, world_object(s, object), e.what()));
      }
    }
  } else {
    for (const std::string& object : data.objects)
      for (const auto& act : data.sensing) replay->check(world_object(s, object), act.name);
  }
}

}  // namespace

EnvironmentFactory make_environment_factory(LoopSettings settings) {
  if (!settings.model) throw std::invalid_argument("make_environment_factory: no problem model");
  if (!settings.classifier)
    throw std::invalid_argument("make_environment_factory: no observation model");
  const pomdp::ObjectIdentificationModel& problem = object_problem(*settings.model);
  std::shared_ptr<const robot::ReplayRecorder> replay;
  if (settings.world.kind == WorldSettings::Kind::replay)
    replay = std::make_shared<const robot::ReplayRecorder>(settings.world.recordings);
  check_world(settings, problem, replay.get());

  auto shared = std::make_shared<const LoopSettings>(std::move(settings));
  auto make = [shared, replay]() {
    const auto& data = object_problem(*shared->model);
    return std::make_unique<RobotEnvironment>(
        shared->model, make_parts(*shared, data, replay.get()), shared->world_objects);
  };
  make();  // RobotEnvironment checks the model against the problem; an InputError here stops all
           // work
  return make;
}

}  // namespace echoplan::experiment
