#include "robot/noisy_recorder.h"

#include <stdexcept>

#include "common/rng.h"
#include "common/stable_hash.h"

namespace echoplan::robot {

namespace {
// The noise's stream under the trial's seed ("noise"), apart from the world's own draws.
constexpr std::uint64_t kNoiseStream = 0x6e6f697365;
}  // namespace

NoisyRecorder::NoisyRecorder(std::unique_ptr<Recorder> inner, WorldNoise noise)
    : inner_(std::move(inner)), noise_(std::move(noise)) {
  if (!inner_ || !noise_.sources)
    throw std::invalid_argument("NoisyRecorder: a recorder and noise sources are needed");
}

void NoisyRecorder::begin_trial(const TrialContext& context) {
  inner_->begin_trial(context);
  trial_seed_ = context.seed;
  performed_.clear();
}

void NoisyRecorder::start(const std::string& action) {
  inner_->start(action);
  action_ = action;
}

audio::AudioClip NoisyRecorder::stop() {
  audio::AudioClip clip = inner_->stop();
  Rng rng(derive_seed(trial_seed_, {kNoiseStream, stable_hash(action_), performed_[action_]++}));
  last_ = noise_.sources->mix(clip, noise_.ebr_db, rng);
  return std::move(last_.clip);
}

}  // namespace echoplan::robot
