// Replay: recordings from a folder stand in for the microphone, so real recordings drive the loop
// without a robot.
//
// ReplayRecorder plays recordings of the trial's true object from DIR/<object>/<action>/* (the
// layout `echoplan synth-recordings` writes and `echoplan train` reads). Which file an action hears
// is drawn from the trial's seed: each action deals its files in an order shuffled once per trial,
// so the same seed replays the same files, and an action repeated within a trial hears a different
// recording each time until its files run out (then the deal starts again).
//
// ReplayRobot is the robot that goes with it: the recordings already hold the motion, so every
// action it knows is reported done at once.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "common/rng.h"
#include "robot/recorder.h"
#include "robot/robot.h"

namespace echoplan::robot {

class ReplayRecorder final : public Recorder {
 public:
  // Indexes the audio files (.wav, .flac, .aif, .aiff, any case) under `directory`. Throws
  // InputError when `directory` is not a readable folder.
  explicit ReplayRecorder(std::filesystem::path directory);

  // Throws InputError naming DIR/<object>/<action> when that folder is missing or holds no audio
  // file.
  void check(const std::string& object, const std::string& action) const;
  // The recordings of (object, action), sorted by path; empty when there are none.
  const std::vector<std::filesystem::path>& recordings(const std::string& object,
                                                       const std::string& action) const;

  // Takes the true object and the trial's seed. Throws InputError when the folder has no recordings
  // of the object at all.
  void begin_trial(const TrialContext& context) override;
  // Chooses the recording `action` will hear. Throws InputError when there is none (see check())
  // and std::logic_error before the first begin_trial().
  void start(const std::string& action) override;
  // Reads the chosen recording (InputError naming the file when it cannot be decoded).
  audio::AudioClip stop() override;
  // The file the last start() chose (for logs).
  const std::filesystem::path& current_file() const { return current_; }

 private:
  struct Deal {
    std::vector<std::size_t> order;  // a permutation of the action's files
    std::size_t next = 0;
  };
  std::filesystem::path directory_;
  std::map<std::string, std::map<std::string, std::vector<std::filesystem::path>>>
      files_;  // object, action
  std::string object_;
  bool in_trial_ = false;
  bool listening_ = false;  // between start() and stop()
  Rng rng_{0};
  std::map<std::string, Deal> deals_;  // this trial's, by action
  std::filesystem::path current_;
};

// The robot of a replayed trial: knows the problem's actions and moves nothing.
class ReplayRobot final : public Robot {
 public:
  explicit ReplayRobot(std::vector<std::string> actions) : actions_(std::move(actions)) {}
  void begin_trial(const TrialContext& /*context*/) override {}
  // Reports `action` done in no time; throws InputError for an action not given at construction.
  ActionReport execute(const std::string& action) override;

 private:
  std::vector<std::string> actions_;
};

}  // namespace echoplan::robot
