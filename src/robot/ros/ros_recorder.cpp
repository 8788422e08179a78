#include "robot/ros/ros_recorder.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <stdexcept>

#include "robot/ros/clip_message.h"
#include "robot/ros/master_watch.h"
#include "robot/ros/ros_protocol.h"
#include "robot/transient_error.h"

namespace echoplan::robot {

namespace {
// How often start() sets the record parameters again while no listener has answered.
constexpr std::chrono::seconds kReassertEvery{1};
}  // namespace

RosRecorder::RosRecorder(ros::NodeHandle& node, double wait_timeout_s)
    : wait_timeout_s_(wait_timeout_s) {
  // Clips can be large (2 s of stereo is 700 kB): keep a few, never drop the one we wait for.
  state_sub_ = node.subscribe(ros_names::kRecordingTopic, 10, &RosRecorder::on_state, this,
                              ros::TransportHints().tcpNoDelay());
  clip_sub_ = node.subscribe(ros_names::kClipTopic, 4, &RosRecorder::on_clip, this,
                             ros::TransportHints().tcpNoDelay());
}

void RosRecorder::on_state(const echoplan_ros::RecordingState::ConstPtr& state) {
  std::lock_guard lock(mutex_);
  ++states_received_;
  last_state_ = *state;
  changed_.notify_all();
}

void RosRecorder::on_clip(const echoplan_ros::Clip::ConstPtr& clip) {
  std::lock_guard lock(mutex_);
  ++clips_received_;
  last_clip_ = clip;
  changed_.notify_all();
}

namespace {
// Sets the record parameters once (set_param_once: never ros::param::set, which retries for ever
// when the master is gone); false when the master did not take them. An empty `action` leaves the
// action parameter as it is.
bool set_record_params(const std::string& action, bool record) {
  return (action.empty() || set_param_once(ros_names::kRecordActionParam, action)) &&
         set_param_once(ros_names::kRecordParam, record);
}
}  // namespace

// The record parameters live on the master: one restarting is waited for (also when it dies
// between our check and our set), one gone ends the run (no recording can start or stop without
// it), never a silent failure of ros::param::set.
void RosRecorder::set_params_on_master(const std::string& action, bool record) const {
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(wait_timeout_s_);
  while (true) {
    const double left = (deadline - ros::WallTime::now()).toSec();
    if (left <= 0 || !wait_for_master(left)) break;
    if (set_record_params(record ? action : "", record)) return;
  }
  throw std::runtime_error(fmt::format(
      "recording '{}': the ROS master at {} does not answer (waited {:g} s), so {} cannot be {}",
      action, ros::master::getURI(), wait_timeout_s_, ros_names::kRecordParam,
      record ? "set" : "cleared"));
}

void RosRecorder::start(const std::string& action) {
  if (recording_) throw std::logic_error("RosRecorder::start: a recording is already running");
  std::unique_lock lock(mutex_);
  const std::uint64_t states_before = states_received_;
  const auto t0 = std::chrono::steady_clock::now();
  lock.unlock();  // the callbacks keep counting states while the master is waited for
  set_params_on_master(action, true);
  lock.lock();
  action_ = action;
  recording_ = true;
  // Wait for a state published after our parameter change that says capture started (or failed).
  const auto reported = [&] {
    return states_received_ > states_before &&
           (last_state_.recording || !last_state_.error.empty());
  };
  const auto deadline = t0 + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                 std::chrono::duration<double>(wait_timeout_s_));
  bool answered = false;
  while (!(answered = changed_.wait_until(
               lock, std::min(deadline, std::chrono::steady_clock::now() + kReassertEvery),
               reported)) &&
         std::chrono::steady_clock::now() < deadline) {
    // A master killed just after the parameters were set took them with it, and its successor
    // never had them: set them again (the same values, which a listener that saw them ignores).
    lock.unlock();
    if (wait_for_master(0.2)) set_record_params(action, true);
    lock.lock();
  }
  if (!answered || !last_state_.error.empty()) {
    const std::string why =
        answered ? "the listener could not start recording: " + last_state_.error
                 : fmt::format(
                       "the listener did not report recording within {:g} s after {} was "
                       "set (is echoplan_listener running?){}",
                       wait_timeout_s_, ros_names::kRecordParam, master_unreachable_note());
    set_record_params("", false);  // best effort: the failure is the message
    recording_ = false;
    throw std::runtime_error(fmt::format("recording '{}': {}", action, why));
  }
  last_start_latency_s_ =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

audio::AudioClip RosRecorder::stop() {
  if (!recording_) throw std::logic_error("RosRecorder::stop: no recording is running");
  recording_ = false;
  capture_ = CaptureReport{};
  std::unique_lock lock(mutex_);
  const std::uint64_t clips_before = clips_received_;
  lock.unlock();  // the callbacks keep counting clips while the master is waited for
  set_params_on_master(action_, false);
  lock.lock();
  const bool answered = changed_.wait_for(lock, std::chrono::duration<double>(wait_timeout_s_),
                                          [&] { return clips_received_ > clips_before; });
  // The listener died mid-recording, or its device vanished: this performance goes unheard, and
  // the next start() waits for a listener (restarted) to report recording.
  if (!answered)
    throw TransientError(
        fmt::format("recording '{}': no clip on {} within {:g} s after {} fell (is "
                    "echoplan_listener running?){}",
                    action_, ros_names::kClipTopic, wait_timeout_s_, ros_names::kRecordParam,
                    master_unreachable_note()));
  const echoplan_ros::Clip::ConstPtr clip = last_clip_;
  lock.unlock();
  capture_.overflow_callbacks = clip->overflow_callbacks;
  capture_.dropped_frames = clip->dropped_frames;
  capture_.stream_error = clip->error;  // the listener's device went away: only part was captured
  if (!clip->error.empty()) {
    if (clip->samples.empty())
      throw TransientError(
          fmt::format("recording '{}': the listener recorded nothing: {}", action_, clip->error));
    ROS_ERROR("recording '%s': %s (keeping the %zu samples captured)", action_.c_str(),
              clip->error.c_str(), clip->samples.size());
  }
  return clip_from_message(*clip, ros_names::kClipTopic);
}

}  // namespace echoplan::robot
