// AudioTopicRecorder and echoplan_listener ~source:=topic against a stand-in for audio_capture
// (audio_capture_stand_in.py, another process), on a real master. Run by audio_topic_test.sh, which
// starts roscore, the stand-in publishing /robot/audio and the listener listening to it.
//
// The stand-in plays a 16 kHz stereo WAV of 16000 frames in chunks of 320 frames, round and round.
// Frame f holds left = L(f), right = R(f) (the script writes them): both multipliers are odd, so
// every left value in the file is different and a clip's first sample says where in the file it
// starts. A clip must therefore be exactly the file's frames from a chunk boundary on, in order.
#include "robot/ros/audio_topic_recorder.h"

#include <gtest/gtest.h>
#include <ros/ros.h>

#include <chrono>
#include <cstdint>
#include <memory>
#include <thread>

#include "common/error.h"
#include "robot/ros/ros_recorder.h"

namespace echoplan::robot {
namespace {

constexpr int kRate = 16000;
constexpr int kFileFrames = 16000;
constexpr int kChunkFrames = 320;
constexpr const char* kTopic = "/robot/audio";

int left_value(long f) { return static_cast<int>((173 * f + 12345) % 65536) - 32768; }
int right_value(long f) { return static_cast<int>((40503 * f + 999) % 65536) - 32768; }

class RosEnvironment : public ::testing::Environment {
 public:
  void SetUp() override {
    ros::init(ros::M_string{}, "audio_topic_recorder_tests", ros::init_options::NoSigintHandler);
    ASSERT_TRUE(ros::master::check()) << "no ROS master: run this through audio_topic_test.sh";
    node_ = std::make_unique<ros::NodeHandle>();
    spinner_ = std::make_unique<ros::AsyncSpinner>(1);  // the global queue (RosRecorder)
    spinner_->start();
  }
  void TearDown() override {
    spinner_->stop();
    node_.reset();
    ros::shutdown();
  }

 private:
  std::unique_ptr<ros::NodeHandle> node_;
  std::unique_ptr<ros::AsyncSpinner> spinner_;
};
const auto* const kEnvironment = ::testing::AddGlobalTestEnvironment(new RosEnvironment);

// Checks that `clip` is the file's frames from a chunk boundary on, in order (wrapping round), and
// returns how many frames it has.
std::size_t expect_published_frames(const audio::AudioClip& clip) {
  EXPECT_EQ(clip.sample_rate, kRate);
  EXPECT_EQ(clip.channels, 2);
  if (clip.channels != 2 || clip.frames() == 0) {
    ADD_FAILURE() << "an empty or mono clip";
    return 0;
  }
  long first = -1;
  for (long f = 0; f < kFileFrames && first < 0; ++f)
    if (static_cast<float>(left_value(f)) / 32768.0f == clip.samples[0]) first = f;
  EXPECT_GE(first, 0) << "the clip's first sample is nowhere in the file";
  EXPECT_EQ(first % kChunkFrames, 0) << "the clip does not start at a chunk";
  std::size_t wrong = 0;
  for (std::size_t i = 0; i < clip.frames(); ++i) {
    const long f = (first + static_cast<long>(i)) % kFileFrames;
    wrong += clip.samples[2 * i] != static_cast<float>(left_value(f)) / 32768.0f;
    wrong += clip.samples[2 * i + 1] != static_cast<float>(right_value(f)) / 32768.0f;
  }
  EXPECT_EQ(wrong, 0u) << "samples differ from the published ones";
  return clip.frames();
}

TopicCaptureConfig stand_in_config() {
  TopicCaptureConfig config;
  config.topic = kTopic;
  config.sample_rate = kRate;
  config.channels = 2;
  config.info_topic = "/robot/audio_info";  // the stand-in's, which agrees
  return config;
}

// A recorder whose subscription is connected: it has heard a chunk (at most 10 s).
std::unique_ptr<AudioTopicRecorder> connected_recorder(const TopicCaptureConfig& config) {
  auto recorder = std::make_unique<AudioTopicRecorder>(ros::NodeHandle(), config);
  const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  recorder->start("warm-up");
  while (recorder->frames_captured() == 0 && std::chrono::steady_clock::now() < until)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  try {
    recorder->stop();
  } catch (const std::runtime_error&) {
  }
  return recorder;
}

TEST(AudioTopicRecorder, ReturnsExactlyTheChunksPublishedBetweenStartAndStop) {
  const auto recorder = connected_recorder(stand_in_config());
  recorder->start("strike");
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  const std::size_t frames = expect_published_frames(recorder->stop());
  EXPECT_EQ(frames % kChunkFrames, 0u) << "whole chunks";
  EXPECT_GE(frames, 2u * kChunkFrames) << "0.3 s is several 20 ms chunks";
  EXPECT_EQ(recorder->last_report().frames, frames);
  EXPECT_EQ(recorder->last_report().misaligned_chunks, 0u);
}

TEST(AudioTopicRecorder, AnActionShorterThanAChunkStillGetsOne) {
  const auto recorder = connected_recorder(stand_in_config());
  for (int i = 0; i < 3; ++i) {
    recorder->start("tap");
    const std::size_t frames = expect_published_frames(recorder->stop());
    EXPECT_GE(frames, static_cast<std::size_t>(kChunkFrames));
  }
}

TEST(AudioTopicRecorder, StopsGrowingAtMaxSeconds) {
  TopicCaptureConfig config = stand_in_config();
  config.max_seconds = 0.05;  // 800 frames: two and a half chunks
  const auto recorder = connected_recorder(config);
  recorder->start("shake");
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  EXPECT_EQ(expect_published_frames(recorder->stop()), 800u);
  EXPECT_TRUE(recorder->last_report().limit_reached);
}

TEST(AudioTopicRecorder, ChunksThatAreNotWholeFramesAreDroppedAndNamed) {
  TopicCaptureConfig config = stand_in_config();
  config.channels = 3;     // 320 stereo frames are 1280 bytes, not a whole number of 6-byte frames
  config.info_topic = "";  // which would say so at start()
  AudioTopicRecorder recorder(ros::NodeHandle(), config);
  // Until the subscription is connected (at most 10 s), a recording hears no chunk at all.
  std::string error;
  const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  do {
    recorder.start("strike");
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    try {
      recorder.stop();
      FAIL() << "a clip from chunks that do not fit the stated channels";
    } catch (const std::runtime_error& e) {
      error = e.what();
    }
  } while (recorder.last_report().chunks == 0 && std::chrono::steady_clock::now() < until);
  EXPECT_NE(error.find("not whole frames of 3 channels"), std::string::npos) << error;
  EXPECT_GT(recorder.last_report().misaligned_chunks, 0u);
  EXPECT_EQ(recorder.last_report().misaligned_chunks, recorder.last_report().chunks);
}

TEST(AudioTopicRecorder, AnAudioInfoThatContradictsTheConfigurationStopsTheStart) {
  TopicCaptureConfig config = stand_in_config();
  config.sample_rate = 44100;
  AudioTopicRecorder recorder(ros::NodeHandle(), config);
  // Until the stand-in's latched AudioInfo has arrived (at most 10 s), start() succeeds.
  std::string error;
  const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  while (error.empty() && std::chrono::steady_clock::now() < until) {
    try {
      recorder.start("strike");
      try {
        recorder.stop();
      } catch (const std::runtime_error&) {
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    } catch (const std::runtime_error& e) {
      error = e.what();
    }
  }
  EXPECT_EQ(error,
            "/robot/audio_info says /robot/audio carries S16LE at 16000 Hz x 2 channels, but the "
            "listener was told S16LE at 44100 Hz x 2");
}

TEST(AudioTopicRecorder, NothingPublishedIsAnErrorSayingSo) {
  TopicCaptureConfig config = stand_in_config();
  config.topic = "/nobody/audio";
  AudioTopicRecorder recorder(ros::NodeHandle(), config);
  recorder.start("strike");
  try {
    recorder.stop();
    FAIL() << "a clip from a topic nobody publishes";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("no node publishes on it"), std::string::npos) << e.what();
  }
}

TEST(TopicCaptureConfig, OnlyS16leAndPositiveRatesAndChannels) {
  auto problem = [](TopicCaptureConfig config) -> std::string {
    try {
      config.validate();
      return "";
    } catch (const InputError& e) {
      return e.what();
    }
  };
  EXPECT_EQ(problem(stand_in_config()), "");
  TopicCaptureConfig config = stand_in_config();
  config.sample_format = "F32LE";
  EXPECT_NE(
      problem(config).find("sample format 'F32LE' on /robot/audio is not supported: only S16LE"),
      std::string::npos)
      << problem(config);
  config = stand_in_config();
  config.sample_rate = 0;
  EXPECT_NE(problem(config).find("sample rate must be >= 1 Hz, got 0"), std::string::npos);
  config.sample_rate = -16000;
  EXPECT_NE(problem(config).find("got -16000"), std::string::npos);
  config = stand_in_config();
  config.channels = 0;
  EXPECT_NE(problem(config).find("channels must be >= 1, got 0"), std::string::npos);
  config = stand_in_config();
  config.max_seconds = 0;
  EXPECT_NE(problem(config).find("max seconds"), std::string::npos);
  // The recorder checks before it subscribes.
  config = stand_in_config();
  config.sample_format = "S24LE";
  EXPECT_THROW(AudioTopicRecorder(ros::NodeHandle(), config), InputError);
}

// The listener node (started by the script with ~source:=topic on the stand-in's topic) publishes
// the same exact frames on /echoplan/clip, through the report's record protocol.
TEST(ListenerNode, PublishesTheTopicsFramesBetweenTheRecordParametersRiseAndFall) {
  ros::NodeHandle node;
  RosRecorder recorder(node, 10.0);
  // The script waited for the listener's subscription; its connection to the publisher follows
  // within moments: until then a recording is empty and fails (at most 10 tries).
  for (int attempt = 0; attempt < 10; ++attempt) {
    recorder.start("warm-up");
    try {
      recorder.stop();
      break;
    } catch (const std::runtime_error&) {
    }
  }
  recorder.start("strike");
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  EXPECT_GE(expect_published_frames(recorder.stop()), 2u * kChunkFrames);
  recorder.start("tap");  // an instant action: the listener waits for a first chunk
  EXPECT_GE(expect_published_frames(recorder.stop()), static_cast<std::size_t>(kChunkFrames));
}

}  // namespace
}  // namespace echoplan::robot
