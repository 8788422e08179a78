// Which world a loop acts in, as a type: the problem's own table, the simulator, replayed
// recordings, or robot parts the caller supplies (a real arm, a live microphone, ROS clients).
// make_world_factory() checks that the world fits the problem and the observation model before
// any trial, then builds a new world each call (one per worker thread of a parallel campaign: the
// problem, the catalogue and the trained model are shared read-only).
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <variant>

#include "loop/dataset_world.h"
#include "loop/robot_world.h"
#include "loop/world.h"
#include "perception/observation_model.h"
#include "pomdp/model.h"
#include "robot/noisy_recorder.h"
#include "sim/catalogue.h"
#include "sim/sim_config.h"

namespace echoplan::loop {

// The world problem's own observation table draws each observation (no sound).
struct TableWorldSpec {};

// MuJoCo + modal synthesis (robot::SimulatedWorld): the simulated arm acts, the simulated
// microphone records, the trained classifier hears.
struct SimulatedWorldSpec {
  std::shared_ptr<const sim::Catalogue> catalogue;  // the objects the world can hold
  std::shared_ptr<const sim::SimConfig> config;     // the lab's variability, microphone, room
};

// Recordings of the true object from DIR/<object>/<action>/*, classified by the trained model.
struct ReplayWorldSpec {
  std::string recordings;
};

// Robot, recorder and observation service supplied by the caller (a real arm, ROS clients). The
// parts exist once: `make` is called once, by the one loop that runs them.
struct PartsWorldSpec {
  std::function<RobotParts()> make;
  std::string description = "robot";  // for messages and logs
};

using WorldSpec = std::variant<TableWorldSpec, SimulatedWorldSpec, ReplayWorldSpec, PartsWorldSpec,
                               DatasetWorldSpec>;

// "model", "simulated", "replay", "dataset" or the parts' description: what trial.json and
// messages call it.
std::string world_name(const WorldSpec& world);

// What a world is built from.
struct WorldInputs {
  WorldSpec spec;
  pomdp::ModelPtr problem;  // scores the world: rewards, observation symbols, the table world's
  std::shared_ptr<const perception::ObservationModel>
      observation_model;  // simulator and replay worlds
  // The world's object when a problem object is the truth (e.g. coffee_mug -> coffee_mug_weighted);
  // objects not listed are themselves. A table world plays the problem object.
  std::map<std::string, std::string> world_objects;
  // Background noise the simulator's and replay's recordings are heard with
  // (robot/noisy_recorder.h); none: as recorded.
  std::optional<robot::WorldNoise> noise;
};

// Builds a new, independent world each call; safe to call from several threads at once (except for
// a PartsWorldSpec, whose parts exist once).
using WorldFactory = std::function<std::unique_ptr<World>()>;

// Checks, before any work, that the parts fit and throws InputError naming what does not:
//   - robot worlds: the problem is an object-identification problem;
//   - simulator: every problem object (after world_objects) has a catalogue entry, and the
//     simulator can execute every sensing action;
//   - replay: the folder holds recordings of every problem object (after world_objects) and
//     sensing action;
//   - dataset: the problem is an object-identification problem whose sensing actions are the
//     data's actions;
//   - simulator and replay: the model has a classifier for every sensing action, reports only the
//     problem's observation symbols and every symbol but `unknown`, and `unknown` only when the
//     problem has that symbol.
// Then returns a factory.
WorldFactory make_world_factory(WorldInputs inputs);

}  // namespace echoplan::loop
