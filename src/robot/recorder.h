// The recorder: listens around an action and hands back what it heard.
//
// Implementations: the simulated microphone (hears the simulated world), a replay recorder (plays
// recordings of the true object from a folder), a live microphone, a ROS listener node.
#pragma once

#include <cstddef>
#include <string>

#include "audio/clip.h"
#include "robot/robot.h"

namespace echoplan::robot {

// What a recording lost on its way in. A recorder that cannot lose anything (the simulated
// microphone, replayed files) reports nothing lost.
struct CaptureReport {
  std::size_t frames = 0;          // frames in the clip stop() returned
  int overflow_callbacks = 0;      // callbacks flagged paInputOverflow by the host (samples lost)
  std::size_t dropped_frames = 0;  // frames lost because the ring was full
  bool limit_reached = false;      // capture stopped at max_seconds
  std::string stream_error;        // non-empty when the stream ended by itself (device gone)

  // The clip has a gap: the sound card or the recorder lost samples, or the device went away.
  bool dropout() const {
    return overflow_callbacks > 0 || dropped_frames > 0 || !stream_error.empty();
  }
};

class Recorder {
 public:
  virtual ~Recorder() = default;
  // Called once per trial before any start(); recorders that depend on the world (replay: which
  // object's recordings to play) read it, a live microphone ignores it.
  virtual void begin_trial(const TrialContext& /*context*/) {}
  // Starts listening; `action` is the action about to be executed (for replay and for file names).
  virtual void start(const std::string& action) = 0;
  // Stops listening and returns everything heard since start(). Throws when nothing could be
  // recorded (no device, device gone) with a message that says why.
  virtual audio::AudioClip stop() = 0;
  // What the last finished recording lost (reset by start()); the loop logs it with the step, so
  // a dropout is counted rather than silent.
  virtual CaptureReport capture_report() const { return {}; }
};

}  // namespace echoplan::robot
