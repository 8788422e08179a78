#include "loop/prepare_observation.h"

#include <fstream>

#include "loop/calibrated_problem.h"
#include "perception/observation_model_json.h"
#include "perception/recording_set.h"
#include "sim/simulated_recordings.h"

namespace echoplan::loop {

namespace {

// The clips a complete training set's manifest lists.
bool complete(const SimulatedTraining& training) {
  std::ifstream manifest(training.directory / "manifest.csv");
  if (!manifest) return false;
  int rows = -1;  // the header
  std::string line;
  while (std::getline(manifest, line)) ++rows;
  return rows ==
         training.per_pair * static_cast<int>(training.objects.size() * training.actions.size());
}

// Trains on `recordings` and saves the model to `save_to` (when named); null when stopped.
std::shared_ptr<const perception::ObservationModel> train(const std::string& recordings,
                                                          const perception::FitOptions& options,
                                                          const std::string& save_to,
                                                          const ProgressFn& progress,
                                                          const std::atomic<bool>& stop) {
  auto model =
      std::make_shared<const perception::ObservationModel>(perception::train_observation_model(
          perception::load_recording_set(recordings), options, progress));
  if (stop.load()) return nullptr;
  if (!save_to.empty()) perception::save_observation_model(*model, save_to);
  return model;
}

}  // namespace

SimulatedTraining training_for(const pomdp::ObjectProblemData& problem,
                               std::shared_ptr<const sim::Catalogue> catalogue,
                               std::shared_ptr<const sim::SimConfig> config, int per_pair,
                               std::uint64_t seed, std::filesystem::path directory) {
  SimulatedTraining training;
  training.catalogue = std::move(catalogue);
  training.config = std::move(config);
  training.objects = problem.objects;
  for (const auto& a : problem.sensing) training.actions.push_back(a.name);
  training.per_pair = per_pair;
  training.seed = seed;
  training.directory = std::move(directory);
  return training;
}

bool synthesise_training_set(const SimulatedTraining& training, const ProgressFn& progress,
                             const std::atomic<bool>& stop) {
  if (training.reuse_complete && complete(training)) return true;
  sim::SimulatedRecordingsOptions options;
  options.objects = training.objects;
  options.actions = training.actions;
  options.per_pair = training.per_pair;
  options.seed = training.seed;
  options.output_dir = training.directory.string();
  const sim::SimulatedRecordingsSummary written = sim::write_simulated_recordings(
      *training.catalogue, *training.config, options,
      [&](const std::string&, int done, int total) {
        if (progress) progress("synthesise", done, total);
      },
      stop);
  return !written.interrupted;
}

PreparedObservation prepare_observation(const ObservationSource& source,
                                        const pomdp::Problem* calibrate,
                                        const std::string& problem_path, const ProgressFn& progress,
                                        const std::atomic<bool>& stop) {
  PreparedObservation prepared;
  if (const auto* file = std::get_if<ModelFile>(&source)) {
    prepared.model = std::make_shared<const perception::ObservationModel>(
        perception::load_observation_model(file->path));
  } else if (const auto* folder = std::get_if<RecordingsTraining>(&source)) {
    prepared.model = train(folder->recordings, folder->train, folder->save_to, progress, stop);
  } else {
    const auto& simulated = std::get<SimulatedTraining>(source);
    if (!synthesise_training_set(simulated, progress, stop)) return prepared;
    prepared.model =
        train(simulated.directory.string(), simulated.train, simulated.save_to, progress, stop);
  }
  if (prepared.model && calibrate)
    prepared.problem = calibrate_problem(*calibrate, *prepared.model, problem_path);
  return prepared;
}

}  // namespace echoplan::loop
