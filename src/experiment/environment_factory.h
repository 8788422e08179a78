// Building closed-loop environments: what a world is made of, checked once, then built as often as
// needed (one per worker thread of a parallel campaign: each gets its own MuJoCo data, recorder and
// clip analyser; the problem, the catalogue and the trained model are shared read-only).
//
//   LoopSettings settings;            // problem, world (simulator or replay), trained model
//   auto factory = make_environment_factory(settings);  // InputError now if anything does not fit
//   auto env = factory();             // in each worker: a RobotEnvironment of its own
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <string>

#include "experiment/robot_environment.h"
#include "perception/observation_model.h"
#include "pomdp/model.h"
#include "sim/catalogue.h"
#include "sim/sim_config.h"

namespace echoplan::experiment {

// Where the sound comes from.
struct WorldSettings {
  enum class Kind {
    simulator,  // MuJoCo + modal synthesis (robot::SimulatedWorld)
    replay,     // recordings of the true object from a folder (robot::ReplayRecorder)
  };
  Kind kind = Kind::simulator;
  sim::Catalogue catalogue;  // simulator: the objects the world can hold
  sim::SimConfig config;     // simulator: the lab's variability, microphone, room
  std::string recordings;    // replay: DIR/<object>/<action>/*
};

struct LoopSettings {
  pomdp::ModelPtr model;  // the problem the planner plans on (an object-identification problem)
  WorldSettings world;
  std::shared_ptr<const perception::ObservationModel> classifier;  // the trained observation model
  // The world's object when a problem object is the truth (e.g. coffee_mug -> coffee_mug_weighted);
  // objects not listed are themselves.
  std::map<std::string, std::string> world_objects;
};

// Builds a new, independent environment each call; safe to call from several threads at once.
using EnvironmentFactory = std::function<std::unique_ptr<RobotEnvironment>()>;

// Checks, before any work, that the parts fit and throws InputError naming what does not:
//   - the problem is an object-identification problem;
//   - simulator: every problem object (after world_objects) has a catalogue entry, and the
//   simulator
//     can execute every sensing action;
//   - replay: the folder holds recordings of every problem object (after world_objects) and sensing
//     action;
//   - the model has a classifier for every sensing action, reports only the problem's observation
//     symbols and every symbol but `unknown`, and `unknown` only when the problem has that symbol.
// Then returns a factory.
EnvironmentFactory make_environment_factory(LoopSettings settings);

}  // namespace echoplan::experiment
