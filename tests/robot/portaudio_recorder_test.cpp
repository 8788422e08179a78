// Live capture through PortAudio, on capture devices that read files (file_capture_device.h), so
// the captured samples can be compared with what the "microphone" was given.
#include "robot/portaudio_recorder.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <thread>

#include "common/error.h"
#include "file_capture_device.h"
#include "robot/transient_error.h"

namespace echoplan::robot {
namespace {

namespace fs = std::filesystem;

constexpr std::size_t kStereoFrames = 44100;  // 1 s of the stereo 44.1 kHz file
constexpr std::size_t kMonoFrames = 16000;    // 1 s of the mono 16 kHz file

// The files the two devices read; written once per test process, before PortAudio starts.
class PortAudioRecorderTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir() = fs::temp_directory_path() / ("echoplan_capture_test_" + std::to_string(::getpid()));
    fs::create_directories(dir());
    stereo() = testing::grid_noise(kStereoFrames * 2, 11);
    mono() = testing::grid_noise(kMonoFrames, 12);
    testing::write_raw_float(dir() / "stereo.raw", stereo());
    testing::write_raw_float(dir() / "mono.raw", mono());
    testing::install_file_capture_devices(
        dir(), {{"stereo_file", dir() / "stereo.raw"}, {"mono_file", dir() / "mono.raw"}});
  }
  static void TearDownTestSuite() { fs::remove_all(dir()); }

  static fs::path& dir() {
    static fs::path d;
    return d;
  }
  static std::vector<float>& stereo() {
    static std::vector<float> s;
    return s;
  }
  static std::vector<float>& mono() {
    static std::vector<float> s;
    return s;
  }

  // Records until the recorder stops by itself (max_seconds) or `timeout` passes.
  static audio::AudioClip record_until_finished(PortAudioRecorder& recorder) {
    recorder.start("strike");
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    while (!recorder.finished() && std::chrono::steady_clock::now() < deadline)
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    return recorder.stop();
  }
};

TEST_F(PortAudioRecorderTest, DefaultsCaptureTheDefaultDeviceAsStereoAt44100Hz) {
  CaptureConfig config;
  config.max_seconds = 0.5;
  PortAudioRecorder recorder(config);
  EXPECT_TRUE(recorder.device().is_default);
  const audio::AudioClip clip = record_until_finished(recorder);
  EXPECT_EQ(clip.sample_rate, 44100);
  EXPECT_EQ(clip.channels, 2);
  ASSERT_EQ(clip.frames(), 22050u);
  // Exactly the file's first 0.5 s, sample for sample.
  const std::vector<float> expected(stereo().begin(), stereo().begin() + 44100);
  EXPECT_EQ(clip.samples, expected);
  EXPECT_TRUE(recorder.capture_report().limit_reached);
  EXPECT_EQ(recorder.capture_report().dropped_frames, 0u);
  EXPECT_EQ(recorder.capture_report().overflow_callbacks, 0);
}

TEST_F(PortAudioRecorderTest, RateChannelsAndDeviceAreConfigurable) {
  CaptureConfig config;
  config.device = "mono_file";
  config.sample_rate = 16000;
  config.channels = 1;
  config.max_seconds = 0.75;
  PortAudioRecorder recorder(config);
  EXPECT_EQ(recorder.device().name, "mono_file");
  const audio::AudioClip clip = record_until_finished(recorder);
  EXPECT_EQ(clip.sample_rate, 16000);
  EXPECT_EQ(clip.channels, 1);
  ASSERT_EQ(clip.frames(), 12000u);
  EXPECT_EQ(clip.samples, std::vector<float>(mono().begin(), mono().begin() + 12000));
}

TEST_F(PortAudioRecorderTest, DeviceCanBeChosenByIndex) {
  int index = -1;
  for (const auto& d : list_input_devices())
    if (d.name == "mono_file") index = d.index;
  ASSERT_GE(index, 0) << "the test device is not listed";
  CaptureConfig config;
  config.device = std::to_string(index);
  config.channels = 1;
  PortAudioRecorder recorder(config);
  EXPECT_EQ(recorder.device().name, "mono_file");
}

TEST_F(PortAudioRecorderTest, StopBeforeTheLimitKeepsEverythingCapturedSoFar) {
  CaptureConfig config;  // max_seconds 600: only stop() ends this recording
  PortAudioRecorder recorder(config);
  recorder.start("slide");
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  while (recorder.frames_captured() < 4096 && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  const audio::AudioClip clip = recorder.stop();
  ASSERT_GE(clip.frames(), 4096u);
  EXPECT_FALSE(recorder.capture_report().limit_reached);
  EXPECT_TRUE(recorder.capture_report().stream_error.empty());
  // It begins with the file (what the file plugin returns past the file's end is its own business).
  const std::size_t n = std::min(clip.samples.size(), stereo().size());
  EXPECT_TRUE(std::equal(clip.samples.begin(),
                         clip.samples.begin() + static_cast<std::ptrdiff_t>(n), stereo().begin()));
}

// The file device delivers faster than real time, so without min_seconds a stop() right after
// start() returns whatever the capture thread got to before it (anything from one buffer to the
// whole recording, depending on scheduling: what made ros_mic flaky). With it, every recording is
// exactly the file's first max_seconds however early stop() comes.
TEST_F(PortAudioRecorderTest, MinSecondsMakesAnEarlyStopWaitForTheWholeRecording) {
  CaptureConfig config;
  config.max_seconds = 0.5;
  config.min_seconds = 0.5;
  PortAudioRecorder recorder(config);
  const std::vector<float> expected(stereo().begin(), stereo().begin() + 44100);
  // Repeated: an early stop cut the clip in about 1 of 5 recordings on an idle machine.
  for (int i = 0; i < 25; ++i) {
    recorder.start("strike");
    const audio::AudioClip clip = recorder.stop();
    ASSERT_EQ(clip.frames(), 22050u) << "recording " << i;
    ASSERT_EQ(clip.samples, expected) << "recording " << i;
    EXPECT_TRUE(recorder.capture_report().limit_reached);
  }
}

TEST_F(PortAudioRecorderTest, MinSecondsBelowMaxSecondsIsALowerBoundOnly) {
  CaptureConfig config;  // max_seconds 600: stop() ends the recording, after at least 0.25 s
  config.min_seconds = 0.25;
  PortAudioRecorder recorder(config);
  recorder.start("slide");
  const audio::AudioClip clip = recorder.stop();
  EXPECT_GE(clip.frames(), 11025u);
  EXPECT_FALSE(recorder.capture_report().limit_reached);
  EXPECT_TRUE(std::equal(clip.samples.begin(), clip.samples.begin() + 22050, stereo().begin()));
}

TEST_F(PortAudioRecorderTest, EachRecordingReopensTheDevice) {
  CaptureConfig config;
  config.max_seconds = 0.1;
  PortAudioRecorder recorder(config);
  const audio::AudioClip first = record_until_finished(recorder);
  const audio::AudioClip second = record_until_finished(recorder);
  EXPECT_EQ(first.samples, second.samples);  // both start at the file's beginning
  EXPECT_EQ(first.frames(), 4410u);
}

TEST_F(PortAudioRecorderTest, UnknownDeviceIsAnInputErrorListingTheDevices) {
  CaptureConfig config;
  config.device = "usb_microphone";
  try {
    PortAudioRecorder recorder(config);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no input device 'usb_microphone'"), std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("'stereo_file'"), std::string::npos) << e.what();
  }
}

TEST_F(PortAudioRecorderTest, UnsupportedRateIsAnInputErrorNamingDeviceAndRate) {
  CaptureConfig config;
  config.sample_rate = 1000000;
  try {
    PortAudioRecorder recorder(config);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("cannot record 2 channels at 1000000 Hz"),
              std::string::npos)
        << e.what();
  }
}

TEST_F(PortAudioRecorderTest, MoreChannelsThanTheDeviceHasIsAnInputError) {
  CaptureConfig config;
  config.channels = 1000;
  EXPECT_THROW(PortAudioRecorder recorder(config), InputError);
}

TEST_F(PortAudioRecorderTest, BadConfigurationIsAnInputErrorNamingTheField) {
  for (auto change :
       {+[](CaptureConfig& c) { c.sample_rate = 0; }, +[](CaptureConfig& c) { c.channels = 0; },
        +[](CaptureConfig& c) { c.frames_per_buffer = 0; },
        +[](CaptureConfig& c) { c.max_seconds = 0; }, +[](CaptureConfig& c) { c.min_seconds = -1; },
        +[](CaptureConfig& c) {
          c.max_seconds = 1;
          c.min_seconds = 2;
        }}) {
    CaptureConfig config;
    change(config);
    EXPECT_THROW(config.validate(), InputError);
    EXPECT_THROW(PortAudioRecorder recorder(config), InputError);
  }
}

TEST_F(PortAudioRecorderTest, StartTwiceAndStopWithoutStartAreLogicErrors) {
  CaptureConfig config;
  PortAudioRecorder recorder(config);
  EXPECT_THROW(recorder.stop(), std::logic_error);
  recorder.start("strike");
  EXPECT_THROW(recorder.start("strike"), std::logic_error);
  EXPECT_NO_THROW(recorder.stop());
}

TEST_F(PortAudioRecorderTest, ADeviceGoneIsATransientErrorNamingItAndItRecordsAgainWhenBack) {
  // The device's file disappears between construction and start(): the stream cannot open.
  const fs::path raw = dir() / "vanishing.raw";
  testing::write_raw_float(raw, mono());
  // A second configuration naming the vanishing device; ALSA rereads its configuration when the
  // file it was told to use changes.
  testing::install_file_capture_devices(
      dir(), {{"stereo_file", dir() / "stereo.raw"}, {"vanishing", raw}});
  CaptureConfig config;
  config.device = "vanishing";
  config.channels = 1;
  config.sample_rate = 16000;
  config.max_seconds = config.min_seconds = 0.5;
  PortAudioRecorder recorder(config);
  fs::remove(raw);
  // TransientError: the loop skips this step's observation and records again at the next step
  // (loop/robot_world.h), rather than ending the run.
  try {
    recorder.start("strike");
    recorder.stop();
    FAIL() << "expected TransientError";
  } catch (const TransientError& e) {
    EXPECT_NE(std::string(e.what()).find("'vanishing'"), std::string::npos) << e.what();
  }
  // Plugged back in: the next recording opens it anew and hears it.
  testing::write_raw_float(raw, mono());
  recorder.start("strike");
  const audio::AudioClip clip = recorder.stop();
  ASSERT_EQ(clip.frames(), 8000u);
  EXPECT_TRUE(std::equal(clip.samples.begin(), clip.samples.end(), mono().begin()));
  EXPECT_FALSE(recorder.capture_report().dropout());
}

}  // namespace
}  // namespace echoplan::robot
