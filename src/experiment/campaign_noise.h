// A campaign's background noise, read once for every kind of world: what its trials hear
// (world.noise) and what an arm `trained_in_noise` learns from (training_set.noise), and the noisy
// copies of a recordings tree that multi-condition training learns from and a dataset world's
// trials hear.
#pragma once

#include <atomic>
#include <filesystem>
#include <optional>
#include <vector>

#include "common/progress.h"
#include "experiment/campaign_arms.h"
#include "experiment/campaign_config.h"
#include "loop/streams.h"
#include "robot/noisy_recorder.h"

namespace echoplan::experiment {

struct CampaignNoise {
  std::optional<robot::WorldNoise> world;     // world.noise: what the trials hear
  std::optional<robot::WorldNoise> training;  // what an arm trained in noise learns from
};

bool any_trained_in_noise(const std::vector<ResolvedArm>& arms);

// Reads the sources now (InputError naming a file that does not decode). The training noise's
// sources default to the world's, its ratio to "-6:24" (from louder than the lab's quiet events to
// noise above them, so that no one level of the trials is the only one it knows). InputError for
// training_set.noise with no arm trained in noise, an arm trained in noise with a given model or
// with no noise to train in.
CampaignNoise load_campaign_noise(const CampaignConfig& config,
                                  const std::vector<ResolvedArm>& arms);

// Writes the noisy copy of the recordings tree `data` to `copy` (loop::write_noisy_copy, seeded
// from the campaign's seed and `stream`; with `keep_quiet` each quiet recording beside its twin,
// both in one session). False when stopped.
bool write_campaign_copy(const CampaignConfig& config, const std::filesystem::path& data,
                         const robot::WorldNoise& noise, const std::filesystem::path& copy,
                         loop::Stream stream, bool keep_quiet, const ProgressFn& progress,
                         const std::atomic<bool>& stop);

}  // namespace echoplan::experiment
