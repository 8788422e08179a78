#include "experiment/simulated_training.h"

#include "perception/recording_set.h"
#include "sim/dataset.h"

namespace echoplan::experiment {

perception::ObservationModel train_on_simulated_recordings(const sim::Catalogue& catalogue,
                                                           const sim::SimConfig& config,
                                                           const SimulatedTraining& training,
                                                           const perception::ProgressFn& progress,
                                                           const std::atomic<bool>& stop) {
  sim::DatasetOptions options;
  options.objects = training.objects;
  options.actions = training.actions;
  options.per_pair = training.per_pair;
  options.seed = training.seed;
  options.output_dir = training.directory.string();
  const sim::DatasetSummary written = sim::write_dataset(
      catalogue, config, options,
      [&](int done, int total, const std::string&) {
        if (progress) progress("synthesise", done, total);
      },
      stop);
  if (written.interrupted) return {};
  return perception::train_observation_model(perception::load_recording_set(options.output_dir),
                                             training.train, progress);
}

}  // namespace echoplan::experiment
