// A robot's own microphone as a Recorder: the audio_common_msgs/AudioData chunks a ROS node (the
// audio_common stack's audio_capture, run with format wave) publishes on a topic.
//
// The chunks carry raw interleaved samples and nothing else: their sample format, rate and channel
// count are stated by the configuration (audio_capture states them on its audio_info topic and
// takes them as parameters). Only S16LE (16-bit signed little-endian, audio_capture's default) is
// read.
//
// The recorder subscribes when it is made and serves its subscription on its own callback queue and
// thread, so it hears chunks whatever its owner's thread does. Semantics follow PortAudioRecorder:
//   - stop() returns every chunk that arrived between start() and stop(), in order, as float
//   samples
//     (value / 32768), the channels kept as they are (frame f, channel c at samples[f * channels +
//     c]);
//   - stop() before the first chunk of the recording arrived (an action shorter than a chunk) waits
//     up to `first_chunk_wait_s` for it, so the clip is not empty;
//   - the clip stops growing at `max_seconds` (exactly that many frames, limit_reached);
//   - a chunk that is not a whole number of frames (wrong channel count, an mp3 stream) is dropped,
//     counted and reported in a warning at stop();
//   - nothing heard: stop() throws std::runtime_error saying whether anyone publishes on the topic;
//   - with `info_topic` set, the publisher's audio_common_msgs/AudioInfo (audio_capture latches it)
//     is checked against the configuration: a different rate, channel count or sample format, or
//     a coding format other than wave, makes start() throw std::runtime_error saying both.
#pragma once

#include <ros/callback_queue.h>
#include <ros/ros.h>

#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "audio/clip.h"
#include "robot/recorder.h"
#include "robot/ros/ros_messages.h"

namespace echoplan::robot {

// What the topic carries and how long to listen. Defaults: audio_capture in the `audio` namespace.
struct TopicCaptureConfig {
  std::string topic = "/audio/audio";
  int sample_rate = 44100;              // Hz, >= 1: the publisher's rate (nothing is resampled)
  int channels = 2;                     // >= 1: the publisher's channel count
  std::string sample_format = "S16LE";  // the only one read
  double max_seconds = 600.0;           // a recording stops growing after this long; > 0
  double first_chunk_wait_s = 0.25;     // see the header comment; >= 0
  std::string info_topic;  // the publisher's AudioInfo (/audio/audio_info); empty: not checked

  // Throws InputError naming the bad field and its value.
  void validate() const;
};

// What was heard and lost in the last recording (reset by start()).
struct TopicCaptureReport {
  std::size_t frames = 0;             // frames in the clip stop() returned
  std::size_t chunks = 0;             // chunks that arrived during the recording
  std::size_t misaligned_chunks = 0;  // of those, dropped: not a whole number of frames
  bool limit_reached = false;         // the clip stopped growing at max_seconds
};

class AudioTopicRecorder final : public Recorder {
 public:
  // Validates `config` (InputError) and subscribes to its topic through `node`'s master.
  AudioTopicRecorder(const ros::NodeHandle& node, const TopicCaptureConfig& config);
  ~AudioTopicRecorder() override;
  AudioTopicRecorder(const AudioTopicRecorder&) = delete;
  AudioTopicRecorder& operator=(const AudioTopicRecorder&) = delete;

  // Starts keeping chunks. Throws logic_error when a recording is already running.
  void start(const std::string& action) override;
  // Stops keeping chunks and returns them (see the header comment).
  audio::AudioClip stop() override;

  // Frames kept so far in the running recording.
  std::size_t frames_captured() const;
  const TopicCaptureReport& last_report() const { return report_; }
  const TopicCaptureConfig& config() const { return config_; }

 private:
  void on_chunk(const audio_common_msgs::AudioData::ConstPtr& chunk);
  void on_info(const audio_common_msgs::AudioInfo::ConstPtr& info);
  // The error stop() throws when the recording is empty.
  std::string nothing_heard_reason() const;

  TopicCaptureConfig config_;
  std::size_t max_frames_;
  ros::CallbackQueue queue_;  // declared before the node, subscriber and spinner that use it
  ros::NodeHandle node_;
  ros::Subscriber subscriber_;
  ros::Subscriber info_subscriber_;
  std::unique_ptr<ros::AsyncSpinner> spinner_;

  mutable std::mutex mutex_;  // guards the members below against on_chunk
  std::condition_variable chunk_arrived_;
  bool started_ = false;  // between start() and stop()
  std::string
      info_mismatch_;  // how the publisher's AudioInfo contradicts config_ (empty: it does not)
  std::vector<float> samples_;
  TopicCaptureReport running_;  // the running recording's counts
  TopicCaptureReport report_;   // the last finished recording's (read by the owner's thread only)
};

}  // namespace echoplan::robot
