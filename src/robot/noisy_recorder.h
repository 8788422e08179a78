// A recorder that hears the world through background noise: whatever another recorder returns (the
// simulated microphone, replayed files, a live microphone) with noise mixed in at an
// event-to-background ratio (sim/background_noise.h), so a trial can be heard as a room where
// people talk or a machine runs would hear it.
//
// The noise is drawn per performance from the trial's seed, the action's name and how many times
// the trial performed it before: the first slide of a trial hears the same noise on every arm of a
// campaign, whatever the arm did before it, as replayed files are dealt the same way
// (robot/replay_recorder.h). Which source, where in it and, for a range, which ratio follow from
// that alone.
#pragma once

#include <map>
#include <memory>
#include <string>

#include "robot/recorder.h"
#include "sim/background_noise.h"

namespace echoplan::robot {

// Background noise a world's recordings are heard with: its sources and the ratio of each
// recording.
struct WorldNoise {
  std::shared_ptr<const sim::BackgroundNoise> sources;
  sim::EbrRange ebr_db;
};

class NoisyRecorder final : public Recorder {
 public:
  // `inner` records; `noise.sources` must not be null.
  NoisyRecorder(std::unique_ptr<Recorder> inner, WorldNoise noise);

  void begin_trial(const TrialContext& context) override;
  void start(const std::string& action) override;
  // The inner recorder's clip with the performance's noise in it.
  audio::AudioClip stop() override;
  CaptureReport capture_report() const override { return inner_->capture_report(); }

  // What the last stop() mixed in: its source and ratio (the clip itself went to the caller).
  const sim::BackgroundNoise::Mixed& last_mix() const { return last_; }

 private:
  std::unique_ptr<Recorder> inner_;
  WorldNoise noise_;
  std::uint64_t trial_seed_ = 0;
  std::string action_;
  std::map<std::string, std::uint64_t> performed_;  // this trial's performances, by action
  sim::BackgroundNoise::Mixed last_;
};

}  // namespace echoplan::robot
