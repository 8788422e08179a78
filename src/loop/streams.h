// The random streams drawn from a user's seed, named once. `echoplan run` and the ROS planner node
// draw the same streams, so the same seed gives them the same log.
#pragma once

#include <cstdint>

#include "common/rng.h"

namespace echoplan::loop {

enum class Stream : std::uint64_t {
  run_training = 1,                  // `echoplan run`: the simulated training set
  run_trial = 2,                     // `echoplan run`, the ROS loop: the trials' streams
  campaign_training = 0x747261696e,  // "train": a campaign's synthesised training set
  campaign_folds = 0x63616c6962,     // "calib": a campaign's cross-validation folds
  campaign_variants = 0x7661726961,  // "varia": recordings of a campaign's variants, for its page
  campaign_unheard = 0x756e686561,   // "unhea": a dataset arm's self-play choosing `unheard: auto`
  campaign_noise = 0x6e6f697365,  // "noise": the noisy copy an arm `trained_in_noise` learns from
  campaign_heard = 0x6865617264,  // "heard": the noisy copy a dataset world's trials hear
};

inline std::uint64_t stream_seed(std::uint64_t seed, Stream stream) {
  return derive_seed(seed, {static_cast<std::uint64_t>(stream)});
}

}  // namespace echoplan::loop
