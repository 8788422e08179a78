#include "experiment/campaign_noise.h"

#include <algorithm>

#include "common/error.h"
#include "loop/noisy_copy.h"
#include "sim/background_noise.h"

namespace echoplan::experiment {

namespace {

constexpr const char* kTrainingEbr = "-6:24";

robot::WorldNoise noise_sources(const NoiseConfig& noise, const std::string& ebr_db) {
  return {std::make_shared<const sim::BackgroundNoise>(noise.sources, noise.talkers),
          sim::parse_ebr(ebr_db)};
}

}  // namespace

bool any_trained_in_noise(const std::vector<ResolvedArm>& arms) {
  return std::any_of(arms.begin(), arms.end(),
                     [](const ResolvedArm& a) { return a.trained_in_noise(); });
}

CampaignNoise load_campaign_noise(const CampaignConfig& config,
                                  const std::vector<ResolvedArm>& arms) {
  CampaignNoise noise;
  const NoiseConfig& world = config.world.noise;
  if (world.given()) noise.world = noise_sources(world, world.ebr_db);
  const NoiseConfig& training = config.training.noise;
  if (!any_trained_in_noise(arms)) {
    if (training.given())
      throw InputError(config.source, 0,
                       "training_set.noise is what an arm `trained_in_noise` learns from, and no "
                       "arm is");
    return noise;
  }
  if (!config.training.model.empty())
    throw InputError(config.source, 0,
                     "an arm trained_in_noise is trained on the training set; training_set.model "
                     "gives one trained model instead: remove one of them");
  const NoiseConfig& sources = training.given() ? training : world;
  if (!sources.given())
    throw InputError(config.source, 0,
                     "an arm trained_in_noise needs noise to train in: give world.noise or "
                     "training_set.noise");
  noise.training =
      noise_sources(sources, training.ebr_db.empty() ? std::string(kTrainingEbr) : training.ebr_db);
  return noise;
}

bool write_campaign_copy(const CampaignConfig& config, const std::filesystem::path& data,
                         const robot::WorldNoise& noise, const std::filesystem::path& copy,
                         loop::Stream stream, bool keep_quiet, const ProgressFn& progress,
                         const std::atomic<bool>& stop) {
  const perception::RecordingSet quiet = perception::load_recording_set(data.string());
  const loop::NoisyCopyOptions options{.seed = loop::stream_seed(config.seed, stream),
                                       .keep_quiet = keep_quiet};
  return loop::write_noisy_copy(quiet, noise, copy, options, progress, stop) ==
         quiet.recordings.size();
}

}  // namespace echoplan::experiment
