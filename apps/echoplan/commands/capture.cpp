// `echoplan devices` and `echoplan record`: the live microphone (PortAudio), for checking a setup
// and recording training sets on a real robot. Built only when PortAudio is found.
#include <fmt/core.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <csignal>
#include <thread>

#include "audio/io.h"
#include "commands/commands.h"
#include "common/error.h"
#include "robot/portaudio_recorder.h"

namespace echoplan::cli {

namespace {

// Ctrl-C ends the recording early; what was captured so far is written.
std::atomic<bool> interrupt_requested{false};
extern "C" void stop_recording_on_sigint(int) { interrupt_requested = true; }

void add_capture_options(CLI::App& cmd, robot::CaptureConfig& config) {
  cmd.add_option("--device", config.device,
                 "Input device: an index or part of a name from `echoplan devices` (default: the "
                 "system's default "
                 "input)");
  cmd.add_option("--rate", config.sample_rate, "Sample rate, Hz")->capture_default_str();
  cmd.add_option("--channels", config.channels, "Channels")->capture_default_str();
}

}  // namespace

void add_devices_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "devices",
      "List the input (capture) devices PortAudio sees: index, host API, input channels, "
      "default rate; '*' marks the default input.\nExample: echoplan devices");
  cmd->callback([] {
    const auto devices = robot::list_input_devices();
    if (devices.empty()) {
      fmt::print("no input devices\n");
      return;
    }
    for (const auto& d : devices)
      fmt::print("{} [{}] {} ({}, {} input channels, {:g} Hz default)\n", d.is_default ? '*' : ' ',
                 d.index, d.name, d.host_api, d.max_input_channels, d.default_sample_rate);
  });
}

void add_record_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("record",
                                 "Record S seconds from an input device into a 16-bit WAV (or "
                                 ".flac), e.g. one training clip while the arm "
                                 "slides or strikes an object.\nExample: echoplan record --seconds "
                                 "2 -o recordings/coffee_mug/strike/001.wav");
  struct Options {
    robot::CaptureConfig capture;
    double seconds = 2.0;
    std::string output;
  };
  auto opt = std::make_shared<Options>();
  cmd->add_option("--seconds", opt->seconds, "How long to record, s")->capture_default_str();
  cmd->add_option("-o,--output", opt->output, "WAV (or .flac) file to write; its folder must exist")
      ->required();
  add_capture_options(*cmd, opt->capture);
  cmd->callback([opt] {
    if (!(opt->seconds > 0) || !std::isfinite(opt->seconds))
      throw InputError("", 0, fmt::format("--seconds must be > 0, got {}", opt->seconds));
    opt->capture.max_seconds = opt->seconds;
    robot::PortAudioRecorder recorder(opt->capture);
    const auto& device = recorder.device();
    fmt::print(stderr, "recording {:g} s from [{}] {} ({} channels, {} Hz)\n", opt->seconds,
               device.index, device.name, opt->capture.channels, opt->capture.sample_rate);

    interrupt_requested = false;
    const auto previous = std::signal(SIGINT, stop_recording_on_sigint);
    recorder.start("record");
    // The recorder stops by itself at max_seconds (exactly that many frames); wait for that, for
    // the stream to end, or for Ctrl-C. The wall-clock guard only matters if the device stalls
    // without an error.
    const auto deadline =
        std::chrono::steady_clock::now() + std::chrono::duration<double>(opt->seconds + 5.0);
    while (!recorder.finished() && !interrupt_requested &&
           std::chrono::steady_clock::now() < deadline)
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    const bool stalled = !recorder.finished() && !interrupt_requested;
    audio::AudioClip clip;
    try {
      clip = recorder.stop();
    } catch (...) {
      std::signal(SIGINT, previous);
      throw;
    }
    std::signal(SIGINT, previous);
    if (stalled)
      fmt::print(stderr,
                 "echoplan: warning: the device delivered only {:.3f} s in {:.1f} s of waiting\n",
                 clip.duration_seconds(), opt->seconds + 5.0);
    if (clip.samples.empty())
      throw std::runtime_error("the device delivered no audio; nothing was written");
    audio::write_audio(opt->output, clip, audio::write_options_for(opt->output));
    fmt::print("wrote {} ({:.3f} s, {} channels, {} Hz)\n", opt->output, clip.duration_seconds(),
               clip.channels, clip.sample_rate);
    if (interrupt_requested) {
      fmt::print(stderr, "echoplan: interrupted; the {:.3f} s recorded before are kept\n",
                 clip.duration_seconds());
      throw Interrupted{};
    }
  });
}

}  // namespace echoplan::cli
