// Live capture from a sound card through PortAudio: the real robot's microphone as a Recorder.
//
// A PortAudioRecorder opens one input stream per recording (start() opens it, stop() closes it), so
// a device unplugged between actions is found at the next start(), and each recording starts clean.
// The audio callback only copies samples into a preallocated single-producer/single-consumer ring;
// a drain thread moves them into the clip, so the callback never allocates or locks.
//
// Defined outcomes (each logged through spdlog):
//   - no input device, an unknown device name, a rate or channel count the device cannot do:
//     InputError from the constructor, naming the device and what it can do;
//   - an input overflow (the sound card dropped samples before PortAudio saw them): a warning at
//     stop() with the number of callbacks that reported one; the clip keeps what was delivered;
//   - the ring full (the drain thread fell behind): the frames that did not fit are dropped,
//   counted
//     and reported in a warning at stop();
//   - the stream ends by itself (the device disappeared or failed): stop() logs an error and
//   returns
//     what was captured before (CaptureReport::stream_error says why); if nothing was, it throws
//     TransientError (robot/transient_error.h) saying so;
//   - the clip reaches CaptureConfig::max_seconds: capture stops there (a recording left running
//     cannot exhaust memory) and stop() returns exactly that many frames;
//   - stop() before the device delivered its first buffer (an action shorter than a device period):
//     stop() waits up to 250 ms for that buffer, so the clip is not empty;
//   - CaptureConfig::min_seconds: stop() waits until the device has delivered that much (at most
//     1 s longer than it should take), so every recording is at least that long whenever stop()
//     comes; a device that falls short is logged as a warning and the clip keeps what arrived.
#pragma once

#include <atomic>
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "audio/clip.h"
#include "robot/recorder.h"

namespace echoplan::robot {

// How to capture. Defaults: the default input device, 2 channels at 44.1 kHz (the report's
// recordings).
struct CaptureConfig {
  // Which input device: empty for the system's default input, a device index as listed by
  // `echoplan devices`, or a (case-sensitive) substring of a device name.
  std::string device;
  int sample_rate = 44100;      // Hz, >= 1
  int channels = 2;             // >= 1
  int frames_per_buffer = 512;  // frames per audio callback (latency vs. callback rate)
  double max_seconds = 600.0;   // a recording stops growing after this long; > 0
  // A recording lasts at least this long (0 <= min_seconds <= max_seconds): stop() waits for the
  // device to deliver it. For a live microphone, the ring of a strike after the arm answered; for
  // a device that reads faster than real time (a file), recordings whose length does not depend on
  // when stop() is called (min_seconds == max_seconds: exactly max_seconds).
  double min_seconds = 0.0;

  // Throws InputError naming the bad field.
  void validate() const;
};

// One input device as PortAudio sees it.
struct InputDevice {
  int index = 0;  // PortAudio device index (stable while the device set is unchanged)
  std::string name;
  std::string host_api;  // e.g. "ALSA", "JACK Audio Connection Kit"
  int max_input_channels = 0;
  double default_sample_rate = 0;  // Hz
  bool is_default = false;         // the default input device of the default host API
};

// Every device with at least one input channel. Throws std::runtime_error when PortAudio cannot
// start.
std::vector<InputDevice> list_input_devices();

class PortAudioRecorder final : public Recorder {
 public:
  // Starts PortAudio, resolves `config.device` and checks that it can record `config.channels`
  // channels at `config.sample_rate` as 32-bit float. Throws InputError otherwise.
  explicit PortAudioRecorder(const CaptureConfig& config);
  ~PortAudioRecorder() override;
  PortAudioRecorder(const PortAudioRecorder&) = delete;
  PortAudioRecorder& operator=(const PortAudioRecorder&) = delete;

  // Opens and starts the input stream. Throws TransientError when the device cannot be opened
  // (gone since construction, busy: it may be back for the next recording) and logic_error when a
  // recording is already running.
  void start(const std::string& action) override;
  // Stops the stream and returns every frame captured since start() (see the defined outcomes
  // above).
  audio::AudioClip stop() override;

  // Frames captured so far in the running recording (for fixed-length recordings).
  std::size_t frames_captured() const;
  // True once the running recording cannot grow any more: max_seconds reached or the stream ended.
  bool finished() const;
  // What happened in the last finished recording.
  CaptureReport capture_report() const override { return report_; }
  // The device actually used.
  const InputDevice& device() const { return device_; }
  const CaptureConfig& config() const { return config_; }

  struct Stream;  // the running stream's shared state (callback, ring, drain thread)

 private:
  // Waits until the device has delivered what every recording must hold: its first buffer, so an
  // instant action is not heard as nothing, and min_seconds.
  void wait_for_minimum(const Stream& s) const;
  CaptureConfig config_;
  InputDevice device_;
  CaptureReport report_;
  std::unique_ptr<Stream> stream_;
};

}  // namespace echoplan::robot
