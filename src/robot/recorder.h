// The recorder: listens around an action and hands back what it heard.
//
// Implementations: the simulated microphone (hears the simulated world), a replay recorder (plays
// recordings of the true object from a folder), a live microphone, a ROS listener node.
#pragma once

#include <string>

#include "audio/clip.h"
#include "robot/robot.h"

namespace echoplan::robot {

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
};

}  // namespace echoplan::robot
