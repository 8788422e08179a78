// echoplan_listener: the original system's listener node. Records while the parameter
// /echoplan/record is true and publishes each recording on /echoplan/clip (and saves it as WAV when
// ~save_dir is set).
//
// Private parameters:
//   ~source        "microphone" (default): capture with PortAudio; "simulation": collect the
//                  clips the simulated robot publishes on /echoplan/sim_clip while recording;
//                  "topic": the robot's own microphone, the audio_common_msgs/AudioData chunks
//                  an audio_capture node publishes (robot/ros/audio_topic_recorder.h)
//   ~device        microphone: input device (index or part of its name; default: the default input)
//   ~rate          Hz (44100), ~channels (2): what the microphone records, or (topic) what the
//                  topic carries: set them to the audio_capture node's sample_rate and channels
//   ~audio_topic   topic: the AudioData topic (/audio/audio)
//   ~sample_format topic: the samples' format (S16LE, the only one read)
//   ~audio_info_topic  topic: the publisher's AudioInfo, checked against ~rate, ~channels and
//                  ~sample_format (default: ~audio_topic + "_info", where audio_capture publishes
//                  it; empty: not checked)
//   ~first_chunk_wait_s  topic: how long a recording that heard nothing yet waits at its end for
//                  a first chunk (0.25)
//   ~max_seconds   a recording stops growing after this long (30)
//   ~min_seconds   microphone: a recording lasts at least this long (0): when the record parameter
//                  falls earlier, capture goes on until the device has delivered it (the ring of a
//                  strike after the arm answered; a file-backed test device: recordings of exactly
//                  ~max_seconds whatever the timing)
//   ~save_dir      when set, each clip is also written to ~save_dir/NNNN_<action>.wav
//   ~poll_hz       how often the record parameter is read (200)
//   ~cached_param  false (default): each read asks the master (one XML-RPC call on loopback,
//                  about 1 ms), so capture starts within a poll period of the flip; true: read
//                  roscpp's cache, which the master updates by pushing - no load on the master,
//                  but the push was measured much slower here (docs/BENCHMARKS.md, "The loop
//                  over ROS")
//   ~sim_clip_wait_s  simulation source: how long to wait at the end of a recording for a clip
//                  still on its way (5.0)
//
// It publishes its state on /echoplan/recording (latched) whenever it starts or stops, so a planner
// knows capture has started before the arm moves (robot/ros/ros_recorder.h).
#include <fmt/format.h>
#include <ros/callback_queue.h>
#include <ros/ros.h>

#include <filesystem>
#include <memory>
#include <optional>

#include "audio/io.h"
#include "common/error.h"
#include "node_main.h"
#include "robot/portaudio_recorder.h"
#include "robot/recorder.h"
#include "robot/ros/audio_topic_recorder.h"
#include "robot/ros/clip_message.h"
#include "robot/ros/master_watch.h"
#include "robot/ros/ros_messages.h"
#include "robot/ros/ros_protocol.h"

namespace {

namespace names = echoplan::robot::ros_names;
using echoplan::audio::AudioClip;

// The clips the simulated robot publishes while a recording runs, concatenated.
class SimulatedSource final : public echoplan::robot::Recorder {
 public:
  SimulatedSource(ros::NodeHandle& node, double wait_s) : wait_s_(wait_s) {
    sub_ = node.subscribe(names::kSimClipTopic, 8, &SimulatedSource::on_clip, this,
                          ros::TransportHints().tcpNoDelay());
  }
  void start(const std::string& /*action*/) override {
    recording_ = true;
    heard_.reset();
  }
  // Waits (spinning) up to wait_s for a clip when none has arrived yet.
  AudioClip stop() override {
    const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(wait_s_);
    while (!heard_ && ros::ok() && ros::WallTime::now() < deadline) {
      ros::getGlobalCallbackQueue()->callAvailable(ros::WallDuration(0.001));
    }
    recording_ = false;
    if (!heard_)
      throw std::runtime_error(
          fmt::format("no clip on {} within {:g} s", names::kSimClipTopic, wait_s_));
    return *std::exchange(heard_, std::nullopt);
  }

 private:
  void on_clip(const echoplan_ros::Clip::ConstPtr& message) {
    if (!recording_) return;
    AudioClip clip = echoplan::robot::clip_from_message(*message, names::kSimClipTopic);
    if (!heard_) {
      heard_ = std::move(clip);
    } else if (heard_->sample_rate == clip.sample_rate && heard_->channels == clip.channels) {
      heard_->samples.insert(heard_->samples.end(), clip.samples.begin(), clip.samples.end());
    } else {
      ROS_ERROR("%s: a clip at %d Hz x %d does not match the recording's %d Hz x %d; dropped",
                names::kSimClipTopic, clip.sample_rate, clip.channels, heard_->sample_rate,
                heard_->channels);
    }
  }

  double wait_s_;
  ros::Subscriber sub_;
  bool recording_ = false;
  std::optional<AudioClip> heard_;
};

template <typename T>
T private_param(ros::NodeHandle& priv, const char* name, T fallback) {
  T value = fallback;
  priv.param<T>(name, value, fallback);
  return value;
}

// The recorder ~source chooses, and what the message of a recording that failed states.
struct Source {
  std::unique_ptr<echoplan::robot::Recorder> recorder;
  const echoplan::robot::PortAudioRecorder* microphone = nullptr;  // for its stream errors
  int sample_rate = 0;  // of a failed recording's message (0: not known)
  int channels = 0;
};

Source microphone_source(ros::NodeHandle& priv, double max_seconds) {
  echoplan::robot::CaptureConfig config;
  config.device = private_param<std::string>(priv, "device", "");
  config.sample_rate = private_param<int>(priv, "rate", 44100);
  config.channels = private_param<int>(priv, "channels", 2);
  config.max_seconds = max_seconds;
  config.min_seconds = private_param<double>(priv, "min_seconds", 0.0);
  auto microphone = std::make_unique<echoplan::robot::PortAudioRecorder>(config);
  ROS_INFO("listening on [%d] %s (%d channels, %d Hz)", microphone->device().index,
           microphone->device().name.c_str(), config.channels, config.sample_rate);
  Source source{nullptr, microphone.get(), config.sample_rate, config.channels};
  source.recorder = std::move(microphone);
  return source;
}

Source topic_source(ros::NodeHandle& node, ros::NodeHandle& priv, double max_seconds) {
  echoplan::robot::TopicCaptureConfig config;
  config.topic = private_param<std::string>(priv, "audio_topic", "/audio/audio");
  config.sample_rate = private_param<int>(priv, "rate", 44100);
  config.channels = private_param<int>(priv, "channels", 2);
  config.sample_format = private_param<std::string>(priv, "sample_format", "S16LE");
  config.first_chunk_wait_s = private_param<double>(priv, "first_chunk_wait_s", 0.25);
  config.info_topic = private_param<std::string>(priv, "audio_info_topic", config.topic + "_info");
  config.max_seconds = max_seconds;
  Source source{std::make_unique<echoplan::robot::AudioTopicRecorder>(node, config), nullptr,
                config.sample_rate, config.channels};
  ROS_INFO("listening to %s (%s, %d channels, %d Hz)", config.topic.c_str(),
           config.sample_format.c_str(), config.channels, config.sample_rate);
  return source;
}

Source make_source(ros::NodeHandle& node, ros::NodeHandle& priv) {
  const std::string source = private_param<std::string>(priv, "source", "microphone");
  const double max_seconds = private_param<double>(priv, "max_seconds", 30.0);
  if (source == "microphone") return microphone_source(priv, max_seconds);
  if (source == "topic") return topic_source(node, priv, max_seconds);
  if (source != "simulation")
    throw echoplan::InputError(
        "~source", 0, fmt::format("'{}' is not 'microphone', 'simulation' or 'topic'", source));
  ROS_INFO("listening to the simulated robot on %s", names::kSimClipTopic);
  return Source{
      std::make_unique<SimulatedSource>(node, private_param<double>(priv, "sim_clip_wait_s", 5.0))};
}

int run(ros::NodeHandle& node, ros::NodeHandle& priv) {
  const std::string save_dir = private_param<std::string>(priv, "save_dir", "");
  const double poll_hz = private_param<double>(priv, "poll_hz", 200.0);
  const bool cached_param = private_param<bool>(priv, "cached_param", false);
  auto read_param = [cached_param](const char* name, auto& value) {
    return cached_param ? ros::param::getCached(name, value) : ros::param::get(name, value);
  };
  const Source source = make_source(node, priv);
  if (!save_dir.empty()) std::filesystem::create_directories(save_dir);

  ros::Publisher clips = node.advertise<echoplan_ros::Clip>(names::kClipTopic, 4);
  ros::Publisher states =
      node.advertise<echoplan_ros::RecordingState>(names::kRecordingTopic, 4, /*latch=*/true);
  auto publish_state = [&](bool recording, const std::string& action, const std::string& error) {
    echoplan_ros::RecordingState state;
    state.recording = recording;
    state.action = action;
    state.error = error;
    states.publish(state);
  };
  publish_state(false, "", "");
  const echoplan::robot::MasterWatch watch;  // no services; its topics are found by themselves

  bool recording = false;
  std::string action;
  std::uint32_t sequence = 0;
  ros::WallRate rate(poll_hz);
  while (ros::ok()) {
    ros::spinOnce();
    // A parameter that cannot be read (the master restarting, which forgets it) keeps its last
    // value: a recording running goes on until the planner lowers the parameter on the new master.
    bool wanted = recording;
    read_param(names::kRecordParam, wanted);
    if (wanted && !recording) {
      action.clear();
      read_param(names::kRecordActionParam, action);
      try {
        source.recorder->start(action);
        recording = true;
        publish_state(true, action, "");
      } catch (const std::exception& e) {
        ROS_ERROR("cannot record '%s': %s", action.c_str(), e.what());
        publish_state(false, action, e.what());
        // Do not retry until the parameter falls and rises again.
        while (ros::ok() && wanted) {
          rate.sleep();
          read_param(names::kRecordParam, wanted);
        }
      }
    } else if (!wanted && recording) {
      recording = false;
      echoplan_ros::Clip message;
      message.sequence = ++sequence;
      message.action = action;
      try {
        const AudioClip clip = source.recorder->stop();
        echoplan::robot::fill_message(clip, message);
        if (source.microphone) {
          // What the sound card lost goes with the clip, so the planner's step log counts it.
          const echoplan::robot::CaptureReport lost = source.microphone->capture_report();
          message.overflow_callbacks = lost.overflow_callbacks;
          message.dropped_frames = lost.dropped_frames;
          if (!lost.stream_error.empty()) message.error = lost.stream_error;
        }
        if (!save_dir.empty()) {
          message.path =
              (std::filesystem::path(save_dir) / fmt::format("{:04d}_{}.wav", sequence, action))
                  .string();
          echoplan::audio::write_audio(message.path, clip);
        }
      } catch (const std::exception& e) {
        ROS_ERROR("recording '%s' failed: %s", action.c_str(), e.what());
        message.error = e.what();
        message.sample_rate = source.sample_rate;
        message.channels = source.channels;
      }
      clips.publish(message);
      publish_state(false, action, "");
    }
    rate.sleep();
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "echoplan_listener");
  ros::NodeHandle node;
  ros::NodeHandle priv("~");
  return echoplan::ros_app::run_node([&] { return run(node, priv); });
}
