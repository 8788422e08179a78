// The loop's observation model, prepared once in memory: loaded from a model file, or trained on a
// folder of recordings, or trained on recordings the simulator synthesises now; and, when asked,
// the problem calibrated to it (loop/calibrated_problem.h). What `echoplan run`, `echoplan train`
// and a campaign call; they write the model and the problem for the user, and never read them back.
#pragma once

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "perception/observation_model.h"
#include "pomdp/problem.h"
#include "sim/catalogue.h"
#include "sim/sim_config.h"

namespace echoplan::loop {

// A trained model file (`echoplan train --out`).
struct ModelFile {
  std::string path;
};

// Recordings DIR/<object>/<action>/*.wav (and DIR/manifest.csv) to train on.
struct RecordingsTraining {
  std::string recordings;
  perception::FitOptions train;
  std::string save_to;  // non-empty: the trained model is saved there for the user
};

// A training set the simulator synthesises now into `directory`, then trains on. With
// `reuse_complete`, a complete set already there (its manifest lists every clip: a resumed
// campaign's) is used as it is.
struct SimulatedTraining {
  std::shared_ptr<const sim::Catalogue> catalogue;
  std::shared_ptr<const sim::SimConfig> config;
  std::vector<std::string> objects;  // catalogue names, the classes
  std::vector<std::string> actions;  // sensing actions
  int per_pair = 10;                 // recordings per (object, action); the report used 10
  std::uint64_t seed = 0;            // the dataset's seed (sim::write_simulated_recordings)
  std::filesystem::path directory;   // where the recordings are written
  perception::FitOptions train;
  bool reuse_complete = false;
  std::string save_to;  // non-empty: the trained model is saved there for the user
};

using ObservationSource = std::variant<ModelFile, RecordingsTraining, SimulatedTraining>;

// A training set of every object and sensing action of `problem`, `per_pair` recordings each,
// synthesised into `directory` from `seed` with the default classifier's options.
SimulatedTraining training_for(const pomdp::ObjectProblemData& problem,
                               std::shared_ptr<const sim::Catalogue> catalogue,
                               std::shared_ptr<const sim::SimConfig> config, int per_pair,
                               std::uint64_t seed, std::filesystem::path directory);

struct PreparedObservation {
  std::shared_ptr<const perception::ObservationModel> model;  // null when stopped
  std::shared_ptr<const pomdp::Problem> problem;  // `calibrate` with the model's table; or null
};

// Loads or trains the model, then calibrates `calibrate` (when given) to it, saying its future
// file is `problem_path`. `progress(stage, done, total)` reports "synthesise" clips and the
// trainer's stages. Throws InputError for an unreadable model or folder, an unknown object or
// action, a model that does not fit `calibrate`; returns a null model when `stop` became true.
PreparedObservation prepare_observation(const ObservationSource& source,
                                        const pomdp::Problem* calibrate,
                                        const std::string& problem_path, const ProgressFn& progress,
                                        const std::atomic<bool>& stop);

// Synthesises `training`'s recordings unless complete already; false when stopped.
bool synthesise_training_set(const SimulatedTraining& training, const ProgressFn& progress,
                             const std::atomic<bool>& stop);

}  // namespace echoplan::loop
