// A Recorder whose microphone is behind ROS, speaking the report's protocol: start() sets the
// parameter /echoplan/record to true, stop() sets it to false, and the listener node
// (echoplan_listener) captures in between and publishes the clip.
//
// Two handshakes make the protocol safe to run fast: start() returns only once the listener reports
// (topic /echoplan/recording) that capture has started, so the arm never moves before the
// microphone listens; stop() returns the clip the listener publishes after the parameter fell.
// Either wait ends after `wait_timeout_s` saying which node did not answer: in start() a
// std::runtime_error (no listener to record with, which ends the run); in stop() a TransientError
// (the listener died mid-recording or its device vanished: the loop skips that performance's
// observation, and the next start() waits for a restarted listener).
//
// Needs a spinner serving the node's callbacks on another thread (ros::AsyncSpinner), because
// start() and stop() block while the answers arrive.
#pragma once

#include <ros/ros.h>

#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <string>

#include "robot/recorder.h"
#include "robot/ros/ros_messages.h"

namespace echoplan::robot {

class RosRecorder final : public Recorder {
 public:
  // `node` must outlive the recorder.
  RosRecorder(ros::NodeHandle& node, double wait_timeout_s);

  void start(const std::string& action) override;
  audio::AudioClip stop() override;
  // What the listener said the last recording lost (its Clip message's counts and error).
  CaptureReport capture_report() const override { return capture_; }

  // Seconds from setting the parameter to true until the listener reported capture started, for the
  // last start() (the capture start latency of docs/BENCHMARKS.md, "The loop over ROS").
  double last_start_latency_s() const { return last_start_latency_s_; }

 private:
  // Sets (record) or clears the record parameters, waiting up to the timeout for the master.
  void set_params_on_master(const std::string& action, bool record) const;
  void on_state(const echoplan_ros::RecordingState::ConstPtr& state);
  void on_clip(const echoplan_ros::Clip::ConstPtr& clip);

  double wait_timeout_s_;
  ros::Subscriber state_sub_;
  ros::Subscriber clip_sub_;
  std::mutex mutex_;
  std::condition_variable changed_;
  std::uint64_t states_received_ = 0;  // guarded by mutex_
  echoplan_ros::RecordingState last_state_;
  std::uint64_t clips_received_ = 0;
  echoplan_ros::Clip::ConstPtr last_clip_;
  std::string action_;
  bool recording_ = false;
  double last_start_latency_s_ = 0;
  CaptureReport capture_;
};

}  // namespace echoplan::robot
