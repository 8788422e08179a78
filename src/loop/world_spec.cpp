#include "loop/world_spec.h"

#include <fmt/format.h>

#include <stdexcept>

#include "common/error.h"
#include "loop/object_problem.h"
#include "loop/table_world.h"
#include "robot/classifier_service.h"
#include "robot/replay_recorder.h"
#include "robot/simulated_sensor_service.h"
#include "robot/simulated_world.h"

namespace echoplan::loop {

namespace {

template <class... Ts>
struct Overloaded : Ts... {
  using Ts::operator()...;
};
template <class... Ts>
Overloaded(Ts...) -> Overloaded<Ts...>;

std::string world_object(const WorldInputs& in, const std::string& object) {
  const auto it = in.world_objects.find(object);
  return it == in.world_objects.end() ? object : it->second;
}

void check_simulator(const WorldInputs& in, const SimulatedWorldSpec& spec,
                     const pomdp::ObjectProblemData& data) {
  if (!spec.catalogue || !spec.config)
    throw std::invalid_argument("SimulatedWorldSpec: a catalogue and a config are needed");
  const robot::SimulatedWorld world(*spec.catalogue, *spec.config, data.sorting);
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
      world.check_object(world_object(in, object));
    } catch (const InputError& e) {
      throw InputError(
          fmt::format("problem '{}' has object '{}', which the simulator cannot hold: {}",
                      data.name, world_object(in, object), e.what()));
    }
  }
}

// A robot world's factory: the parts come from `make_parts` (each call a new set), the problem
// and the classifier checks from RobotWorld's constructor, made once now.
WorldFactory robot_world_factory(const WorldInputs& in, std::function<RobotParts()> make_parts) {
  auto problem = in.problem;
  auto objects = in.world_objects;
  auto make = [problem, objects, make_parts]() -> std::unique_ptr<World> {
    return std::make_unique<RobotWorld>(problem, make_parts(), objects);
  };
  return make;
}

// `make_parts` with the world's background noise in every recording.
std::function<RobotParts()> heard_through(std::function<RobotParts()> make_parts,
                                          const std::optional<robot::WorldNoise>& noise) {
  if (!noise) return make_parts;
  return [make_parts = std::move(make_parts), noise = *noise] {
    RobotParts parts = make_parts();
    parts.recorder = std::make_unique<robot::NoisyRecorder>(std::move(parts.recorder), noise);
    return parts;
  };
}

}  // namespace

std::string world_name(const WorldSpec& world) {
  return std::visit(Overloaded{[](const TableWorldSpec&) { return std::string("model"); },
                               [](const SimulatedWorldSpec&) { return std::string("simulated"); },
                               [](const ReplayWorldSpec&) { return std::string("replay"); },
                               [](const PartsWorldSpec& p) { return p.description; },
                               [](const DatasetWorldSpec&) { return std::string("dataset"); }},
                    world);
}

WorldFactory make_world_factory(WorldInputs in) {
  if (!in.problem) throw std::invalid_argument("make_world_factory: no problem model");
  if (in.noise && !std::holds_alternative<SimulatedWorldSpec>(in.spec) &&
      !std::holds_alternative<ReplayWorldSpec>(in.spec))
    throw InputError(fmt::format(
        "background noise is heard by the simulated and the replayed worlds, not by the {} world "
        "(for recorded data, write a noisy copy with `echoplan add-noise` and replay that)",
        world_name(in.spec)));
  if (const auto* parts = std::get_if<PartsWorldSpec>(&in.spec))
    return robot_world_factory(in, parts->make);
  if (std::holds_alternative<TableWorldSpec>(in.spec)) {
    auto problem = in.problem;
    return [problem]() -> std::unique_ptr<World> { return std::make_unique<TableWorld>(problem); };
  }
  if (const auto* dataset = std::get_if<DatasetWorldSpec>(&in.spec)) {
    auto problem = in.problem;
    const DatasetWorldSpec spec = *dataset;
    const pomdp::ObjectIdentificationModel& model = object_problem(*problem);
    DatasetWorld check(model, spec);  // the actions fit: an InputError stops all work now
    return [problem, spec]() -> std::unique_ptr<World> {
      return std::make_unique<DatasetWorld>(object_problem(*problem), spec);
    };
  }
  if (!in.observation_model)
    throw std::invalid_argument("make_world_factory: no observation model");
  const pomdp::ObjectProblemData& data = object_problem(*in.problem).data();
  auto model = in.observation_model;
  std::function<RobotParts()> make_parts;
  if (const auto* simulated = std::get_if<SimulatedWorldSpec>(&in.spec)) {
    check_simulator(in, *simulated, data);
    const SimulatedWorldSpec spec = *simulated;
    const std::vector<std::string> sorting = data.sorting;
    make_parts = [spec, sorting, model] {
      auto world = std::make_shared<robot::SimulatedWorld>(*spec.catalogue, *spec.config, sorting);
      // A model that also reads the arm's sensors hears them from the world's physics.
      std::unique_ptr<robot::ObservationService> service;
      if (robot::SimulatedSensorService::reads_sensors(*model))
        service = std::make_unique<robot::SimulatedSensorService>(world, model);
      else
        service = std::make_unique<robot::ClassifierService>(model);
      return RobotParts{std::make_unique<robot::SimulatedArm>(world),
                        std::make_unique<robot::SimulatedMicrophone>(world), std::move(service),
                        RecordingChecks{}};  // exact recordings: no level or length checks
    };
  } else {
    // The folder is indexed once; every world deals its own files from a copy of the index.
    auto replay = std::make_shared<const robot::ReplayRecorder>(
        std::get<ReplayWorldSpec>(in.spec).recordings);
    for (const std::string& object : data.objects)
      for (const auto& act : data.sensing) replay->check(world_object(in, object), act.name);
    const std::vector<std::string> actions = in.problem->spec().action_names;
    make_parts = [replay, actions, model] {
      return RobotParts{std::make_unique<robot::ReplayRobot>(actions),
                        std::make_unique<robot::ReplayRecorder>(*replay),
                        std::make_unique<robot::ClassifierService>(model),
                        RecordingChecks{}};  // recorded files: heard as they are
    };
  }
  WorldFactory factory = robot_world_factory(in, heard_through(std::move(make_parts), in.noise));
  factory();  // RobotWorld checks the classifier against the problem: an InputError stops all work
  return factory;
}

}  // namespace echoplan::loop
