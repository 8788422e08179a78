// Test fixture shared by the robot and experiment tests: a few simulated recordings per object and
// action written to a temporary folder, and the observation model trained on them (the real
// pipeline: sim::write_simulated_recordings, perception::load_recording_set,
// perception::train_observation_model).
#pragma once

#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "../common/source_dir.h"
#include "perception/observation_model.h"
#include "perception/recording_set.h"
#include "sim/catalogue.h"
#include "sim/simulated_recordings.h"

namespace echoplan::testing {

inline const sim::Catalogue& shipped_catalogue() {
  static const sim::Catalogue c =
      sim::load_catalogue(echoplan::testing::source_dir() + "/objects/catalogue.yaml");
  return c;
}

// A folder name no other test process uses.
inline std::filesystem::path unique_temp_dir(const std::string& what) {
  static int count = 0;
  return std::filesystem::temp_directory_path() /
         ("echoplan_" + what + "_" + std::to_string(::getpid()) + "_" + std::to_string(count++));
}

// Writes `per_pair` recordings of each (object, action) into `dir` (replaced).
inline void write_small_dataset(const std::filesystem::path& dir,
                                const std::vector<std::string>& objects,
                                const std::vector<std::string>& actions, int per_pair,
                                std::uint64_t seed) {
  std::filesystem::remove_all(dir);
  sim::SimulatedRecordingsOptions options;
  options.objects = objects;
  options.actions = actions;
  options.per_pair = per_pair;
  options.seed = seed;
  options.output_dir = dir.string();
  const std::atomic<bool> never{false};
  sim::write_simulated_recordings(shipped_catalogue(), sim::SimConfig{}, options, {}, never);
}

// A model trained on `per_pair` simulated recordings per (object, action).
inline std::shared_ptr<const perception::ObservationModel> train_small_model(
    const std::vector<std::string>& objects, const std::vector<std::string>& actions, int per_pair,
    bool reject = true) {
  const auto dir = unique_temp_dir("training");
  write_small_dataset(dir, objects, actions, per_pair, 1);
  perception::FitOptions options;
  options.reject = reject;
  auto model = std::make_shared<const perception::ObservationModel>(
      perception::train_observation_model(perception::load_recording_set(dir.string()), options));
  std::filesystem::remove_all(dir);
  return model;
}

}  // namespace echoplan::testing
