#include "robot/ros/audio_topic_recorder.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "common/error.h"
#include "robot/ros/s16le_chunk.h"

namespace echoplan::robot {

void TopicCaptureConfig::validate() const {
  if (topic.empty()) throw InputError("", 0, "the audio topic is empty");
  if (sample_format != "S16LE")
    throw InputError("", 0,
                     fmt::format("sample format '{}' on {} is not supported: only S16LE (16-bit "
                                 "signed little-endian; audio_capture's sample_format)",
                                 sample_format, topic));
  if (sample_rate < 1)
    throw InputError("", 0, fmt::format("sample rate must be >= 1 Hz, got {}", sample_rate));
  if (channels < 1) throw InputError("", 0, fmt::format("channels must be >= 1, got {}", channels));
  if (!(max_seconds > 0))
    throw InputError("", 0, fmt::format("max seconds must be > 0, got {}", max_seconds));
  if (!(first_chunk_wait_s >= 0))
    throw InputError("", 0,
                     fmt::format("first chunk wait must be >= 0 s, got {}", first_chunk_wait_s));
}

AudioTopicRecorder::AudioTopicRecorder(const ros::NodeHandle& node,
                                       const TopicCaptureConfig& config)
    : config_(config), node_(node) {
  config_.validate();
  max_frames_ = std::max<std::size_t>(
      static_cast<std::size_t>(std::llround(config_.max_seconds * config_.sample_rate)), 1);
  // Our own queue and thread: stop() can then wait for a chunk while its caller's thread (the
  // listener's loop, a test) does not spin.
  node_.setCallbackQueue(&queue_);
  // A robot publishes a chunk every few milliseconds; keep a second's worth queued.
  subscriber_ = node_.subscribe(config_.topic, 200, &AudioTopicRecorder::on_chunk, this,
                                ros::TransportHints().tcpNoDelay());
  if (!config_.info_topic.empty())
    info_subscriber_ = node_.subscribe(config_.info_topic, 1, &AudioTopicRecorder::on_info, this);
  spinner_ = std::make_unique<ros::AsyncSpinner>(1, &queue_);
  spinner_->start();
}

AudioTopicRecorder::~AudioTopicRecorder() {
  spinner_->stop();
  subscriber_.shutdown();
  info_subscriber_.shutdown();
}

void AudioTopicRecorder::on_info(const audio_common_msgs::AudioInfo::ConstPtr& info) {
  std::string mismatch;
  if (info->coding_format != "wave")
    mismatch = fmt::format("coding format '{}', not raw audio (run audio_capture with format wave)",
                           info->coding_format);
  else if (info->sample_format != config_.sample_format ||
           static_cast<long long>(info->sample_rate) != config_.sample_rate ||
           info->channels != config_.channels)
    mismatch = fmt::format("{} at {} Hz x {} channels, but the listener was told {} at {} Hz x {}",
                           info->sample_format, info->sample_rate, info->channels,
                           config_.sample_format, config_.sample_rate, config_.channels);
  if (!mismatch.empty())
    mismatch = fmt::format("{} says {} carries {}", config_.info_topic, config_.topic, mismatch);
  if (!mismatch.empty()) ROS_ERROR("%s", mismatch.c_str());
  std::lock_guard lock(mutex_);
  info_mismatch_ = mismatch;
}

void AudioTopicRecorder::on_chunk(const audio_common_msgs::AudioData::ConstPtr& chunk) {
  std::lock_guard lock(mutex_);
  if (!started_ || running_.limit_reached) return;
  ++running_.chunks;
  const ChunkOutcome outcome =
      append_s16le_chunk(chunk->data, config_.channels, max_frames_, samples_);
  if (outcome.misaligned) ++running_.misaligned_chunks;
  if (outcome.limit_reached) running_.limit_reached = true;
  chunk_arrived_.notify_all();
}

void AudioTopicRecorder::start(const std::string& /*action*/) {
  std::lock_guard lock(mutex_);
  if (started_) throw std::logic_error("AudioTopicRecorder::start: a recording is already running");
  if (!info_mismatch_.empty()) throw std::runtime_error(info_mismatch_);
  samples_.clear();
  running_ = TopicCaptureReport{};
  started_ = true;
}

std::size_t AudioTopicRecorder::frames_captured() const {
  std::lock_guard lock(mutex_);
  return samples_.size() / static_cast<std::size_t>(config_.channels);
}

audio::AudioClip AudioTopicRecorder::stop() {
  std::unique_lock lock(mutex_);
  if (!started_) throw std::logic_error("AudioTopicRecorder::stop: no recording is running");
  chunk_arrived_.wait_for(lock, std::chrono::duration<double>(config_.first_chunk_wait_s),
                          [this] { return running_.chunks > 0; });
  started_ = false;
  audio::AudioClip clip;
  clip.sample_rate = config_.sample_rate;
  clip.channels = config_.channels;
  clip.samples = std::move(samples_);
  samples_ = {};
  report_ = running_;
  report_.frames = clip.frames();
  lock.unlock();

  if (report_.misaligned_chunks > 0)
    ROS_WARN(
        "%s: %zu of %zu chunks were not whole frames of %d channels x 16 bits and were "
        "dropped",
        config_.topic.c_str(), report_.misaligned_chunks, report_.chunks, config_.channels);
  if (report_.limit_reached)
    ROS_INFO("%s: the recording reached its limit of %g s and stopped growing",
             config_.topic.c_str(), config_.max_seconds);
  if (clip.samples.empty()) throw std::runtime_error(nothing_heard_reason());
  return clip;
}

std::string AudioTopicRecorder::nothing_heard_reason() const {
  if (report_.misaligned_chunks > 0)
    return fmt::format(
        "nothing recorded from {}: its {} chunks were not whole frames of {} channels x 16 bits "
        "(does the channel count match the publisher's, and does it publish raw audio, "
        "audio_capture's format wave?)",
        config_.topic, report_.chunks, config_.channels);
  if (subscriber_.getNumPublishers() == 0)
    return fmt::format(
        "nothing recorded from {}: no node publishes on it (is audio_capture "
        "running, in that namespace?)",
        config_.topic);
  return fmt::format("nothing recorded from {}: no chunk arrived within {:g} s of the start",
                     config_.topic, config_.first_chunk_wait_s);
}

}  // namespace echoplan::robot
