// A trained observation model from scratch: synthesise a training set with the simulator, then
// train and calibrate the classifier on it (what `echoplan run` does when no model is given).
#pragma once

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "perception/observation_model.h"
#include "sim/catalogue.h"
#include "sim/sim_config.h"

namespace echoplan::experiment {

struct SimulatedTraining {
  std::vector<std::string> objects;  // catalogue names, the classes
  std::vector<std::string> actions;  // sensing actions
  int per_pair = 10;                 // recordings per (object, action); the seed report used 10
  std::uint64_t seed = 0;            // the dataset's seed (sim::write_dataset)
  std::filesystem::path
      directory;  // where the recordings are written (DIR/<object>/<action>/*.wav)
  perception::TrainOptions train;
};

// Writes the recordings, then trains on them. `progress(stage, done, total)` reports both stages
// ("synthesise", then the trainer's stages). Throws InputError for an unknown object or action or
// an unwritable directory; returns an untrained model when `stop` became true (check it).
perception::ObservationModel train_on_simulated_recordings(const sim::Catalogue& catalogue,
                                                           const sim::SimConfig& config,
                                                           const SimulatedTraining& training,
                                                           const perception::ProgressFn& progress,
                                                           const std::atomic<bool>& stop);

}  // namespace echoplan::experiment
