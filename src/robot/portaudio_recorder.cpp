#include "robot/portaudio_recorder.h"

#include <fmt/format.h>
#include <portaudio.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstring>
#include <mutex>
#include <stdexcept>
#include <thread>

#include "common/error.h"
#include "robot/transient_error.h"

namespace echoplan::robot {
namespace {

// PortAudio counts Pa_Initialize/Pa_Terminate pairs itself, so each user holds one of these.
struct PortAudioSession {
  PortAudioSession() {
    const PaError err = Pa_Initialize();
    if (err != paNoError)
      throw std::runtime_error(fmt::format("PortAudio cannot start: {}", Pa_GetErrorText(err)));
  }
  ~PortAudioSession() { Pa_Terminate(); }
  PortAudioSession(const PortAudioSession&) = delete;
  PortAudioSession& operator=(const PortAudioSession&) = delete;
};

InputDevice describe(PaDeviceIndex index) {
  const PaDeviceInfo* info = Pa_GetDeviceInfo(index);
  const PaHostApiInfo* api = info ? Pa_GetHostApiInfo(info->hostApi) : nullptr;
  InputDevice d;
  d.index = index;
  d.name = info ? info->name : "?";
  d.host_api = api ? api->name : "?";
  d.max_input_channels = info ? info->maxInputChannels : 0;
  d.default_sample_rate = info ? info->defaultSampleRate : 0;
  d.is_default = index == Pa_GetDefaultInputDevice();
  return d;
}

std::vector<InputDevice> input_devices() {
  std::vector<InputDevice> devices;
  const PaDeviceIndex count = Pa_GetDeviceCount();
  for (PaDeviceIndex i = 0; i < count; ++i) {
    const PaDeviceInfo* info = Pa_GetDeviceInfo(i);
    if (info && info->maxInputChannels > 0) devices.push_back(describe(i));
  }
  return devices;
}

std::string device_list_text(const std::vector<InputDevice>& devices) {
  if (devices.empty()) return "there are no input devices";
  std::string text = "input devices:";
  for (const auto& d : devices) text += fmt::format(" [{}] '{}'", d.index, d.name);
  return text;
}

// The device `spec` names: empty for the default input, an index, or a name substring (the first
// match).
InputDevice resolve_device(const std::string& spec) {
  const auto devices = input_devices();
  if (spec.empty()) {
    const PaDeviceIndex index = Pa_GetDefaultInputDevice();
    if (index == paNoDevice)
      throw InputError("", 0, "no default input device (" + device_list_text(devices) + ")");
    return describe(index);
  }
  const bool is_index =
      std::all_of(spec.begin(), spec.end(), [](char c) { return c >= '0' && c <= '9'; });
  for (const auto& d : devices) {
    if (is_index ? std::to_string(d.index) == spec : d.name.find(spec) != std::string::npos)
      return d;
  }
  throw InputError("", 0,
                   fmt::format("no input device '{}' ({})", spec, device_list_text(devices)));
}

PaStreamParameters stream_parameters(const InputDevice& device, const CaptureConfig& config) {
  PaStreamParameters p{};
  p.device = device.index;
  p.channelCount = config.channels;
  p.sampleFormat = paFloat32;
  p.suggestedLatency = Pa_GetDeviceInfo(device.index)->defaultLowInputLatency;
  p.hostApiSpecificStreamInfo = nullptr;
  return p;
}

}  // namespace

void CaptureConfig::validate() const {
  if (sample_rate < 1)
    throw InputError("", 0, fmt::format("sample rate must be >= 1 Hz, got {}", sample_rate));
  if (channels < 1) throw InputError("", 0, fmt::format("channels must be >= 1, got {}", channels));
  if (frames_per_buffer < 1)
    throw InputError("", 0,
                     fmt::format("frames per buffer must be >= 1, got {}", frames_per_buffer));
  if (!(max_seconds > 0))
    throw InputError("", 0, fmt::format("max seconds must be > 0, got {}", max_seconds));
  if (!(min_seconds >= 0 && min_seconds <= max_seconds))
    throw InputError("", 0,
                     fmt::format("min seconds must be between 0 and max seconds ({}), got {}",
                                 max_seconds, min_seconds));
}

std::vector<InputDevice> list_input_devices() {
  PortAudioSession session;
  return input_devices();
}

// The state a running recording shares between the audio callback (producer), the drain thread
// (consumer) and stop(). The ring holds interleaved samples; `head`/`tail` count samples ever
// written and read, so the ring is full when head - tail == ring.size().
struct PortAudioRecorder::Stream {
  PortAudioSession session;
  PaStream* pa = nullptr;
  int channels = 2;
  std::size_t max_frames = 0;
  std::size_t min_frames = 0;  // stop() waits for these (CaptureConfig::min_seconds)
  std::chrono::steady_clock::time_point started;

  std::vector<float> ring;
  std::atomic<std::size_t> head{0};
  std::atomic<std::size_t> tail{0};
  std::atomic<std::size_t> frames_delivered{0};  // frames the callback accepted (<= max_frames)
  std::atomic<std::size_t> dropped_frames{0};
  std::atomic<int> overflow_callbacks{0};
  std::atomic<bool> limit_reached{false};
  std::atomic<bool> stream_ended{false};  // set by the stream-finished callback

  std::vector<float> clip;  // drained samples; only the drain thread touches it until it is joined
  std::atomic<std::size_t> clip_frames{0};
  std::mutex wake_mutex;
  std::condition_variable wake;
  bool stopping = false;  // guarded by wake_mutex
  std::thread drainer;

  static int on_audio(const void* input, void*, unsigned long frame_count,
                      const PaStreamCallbackTimeInfo*, PaStreamCallbackFlags flags, void* user) {
    auto& s = *static_cast<Stream*>(user);
    if (flags & paInputOverflow) s.overflow_callbacks.fetch_add(1, std::memory_order_relaxed);
    const std::size_t delivered = s.frames_delivered.load(std::memory_order_relaxed);
    const std::size_t frames = std::min<std::size_t>(frame_count, s.max_frames - delivered);
    const std::size_t samples = frames * static_cast<std::size_t>(s.channels);
    const std::size_t head = s.head.load(std::memory_order_relaxed);
    const std::size_t free = s.ring.size() - (head - s.tail.load(std::memory_order_acquire));
    if (samples > free) {
      // The drain thread fell behind: drop this whole buffer rather than split a frame.
      s.dropped_frames.fetch_add(frames, std::memory_order_relaxed);
    } else if (input != nullptr && samples > 0) {
      const auto* in = static_cast<const float*>(input);
      const std::size_t at = head % s.ring.size();
      const std::size_t first = std::min(samples, s.ring.size() - at);
      std::memcpy(s.ring.data() + at, in, first * sizeof(float));
      std::memcpy(s.ring.data(), in + first, (samples - first) * sizeof(float));
      s.head.store(head + samples, std::memory_order_release);
    }
    s.frames_delivered.store(delivered + frames, std::memory_order_relaxed);
    if (delivered + frames >= s.max_frames) {
      s.limit_reached.store(true, std::memory_order_release);
      return paComplete;
    }
    return paContinue;
  }

  static void on_finished(void* user) {
    auto& s = *static_cast<Stream*>(user);
    s.stream_ended.store(true, std::memory_order_release);
    s.wake.notify_all();
  }

  // Moves everything in the ring into the clip.
  void drain() {
    const std::size_t head_now = head.load(std::memory_order_acquire);
    std::size_t t = tail.load(std::memory_order_relaxed);
    while (t < head_now) {
      const std::size_t at = t % ring.size();
      const std::size_t n = std::min(head_now - t, ring.size() - at);
      clip.insert(clip.end(), ring.begin() + static_cast<std::ptrdiff_t>(at),
                  ring.begin() + static_cast<std::ptrdiff_t>(at + n));
      t += n;
    }
    tail.store(t, std::memory_order_release);
    clip_frames.store(clip.size() / static_cast<std::size_t>(channels), std::memory_order_release);
  }

  // The drain thread: empties the ring every few milliseconds (a quarter of its capacity is always
  // well ahead of that) until stop() asks it to finish.
  void drain_loop() {
    std::unique_lock lock(wake_mutex);
    while (!stopping) {
      wake.wait_for(lock, std::chrono::milliseconds(5));
      lock.unlock();
      drain();
      lock.lock();
    }
    lock.unlock();
    drain();
  }
};

PortAudioRecorder::PortAudioRecorder(const CaptureConfig& config) : config_(config) {
  config_.validate();
  PortAudioSession session;
  device_ = resolve_device(config_.device);
  if (device_.max_input_channels < config_.channels)
    throw InputError(
        "", 0,
        fmt::format("input device [{}] '{}' has {} input channels; {} were asked for",
                    device_.index, device_.name, device_.max_input_channels, config_.channels));
  const PaStreamParameters p = stream_parameters(device_, config_);
  const PaError err = Pa_IsFormatSupported(&p, nullptr, config_.sample_rate);
  if (err != paFormatIsSupported)
    throw InputError(
        "", 0,
        fmt::format(
            "input device [{}] '{}' cannot record {} channels at {} Hz: {} (its default rate is "
            "{} Hz)",
            device_.index, device_.name, config_.channels, config_.sample_rate,
            Pa_GetErrorText(err), device_.default_sample_rate));
}

PortAudioRecorder::~PortAudioRecorder() {
  if (!stream_) return;
  try {
    stop();
  } catch (const std::exception& e) {
    spdlog::error("capture: {}", e.what());
  }
}

namespace {

// An action can end before the device has delivered its first buffer (a simulated arm acts in
// milliseconds; a device hands over audio a period at a time). A recording around it is then
// empty, which no one can classify, so stop() waits for the first buffer of a healthy stream:
// at most kFirstBufferWait, a few device periods.
constexpr std::chrono::milliseconds kFirstBufferWait{250};
// How late a device may be with min_seconds before stop() gives up waiting: a live device delivers
// it within a few periods of min_seconds after start; one that reads a file delivers it at once
// unless the process is starved of CPU. Longer than either, short enough for a stalled device.
constexpr std::chrono::seconds kMinimumSlack{1};

}  // namespace

void PortAudioRecorder::wait_for_minimum(const Stream& s) const {
  using Clock = std::chrono::steady_clock;
  const std::size_t wanted = std::max<std::size_t>(s.min_frames, 1);
  const auto until =
      std::max(Clock::now() + kFirstBufferWait,
               s.started + std::chrono::duration_cast<Clock::duration>(
                               std::chrono::duration<double>(config_.min_seconds) + kMinimumSlack));
  while (s.frames_delivered.load(std::memory_order_acquire) < wanted &&
         !s.stream_ended.load(std::memory_order_acquire) && Pa_IsStreamActive(s.pa) == 1 &&
         Clock::now() < until)
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  const std::size_t delivered = s.frames_delivered.load(std::memory_order_acquire);
  if (s.min_frames > 0 && delivered < s.min_frames)
    spdlog::warn(
        "capture: [{}] '{}' delivered {} of the {} frames a recording must hold (min {} s); "
        "keeping what arrived",
        device_.index, device_.name, delivered, s.min_frames, config_.min_seconds);
}

void PortAudioRecorder::start(const std::string& action) {
  if (stream_) throw std::logic_error("PortAudioRecorder::start: a recording is already running");
  report_ = CaptureReport{};
  auto s = std::make_unique<Stream>();
  s->channels = config_.channels;
  s->max_frames = static_cast<std::size_t>(std::llround(config_.max_seconds * config_.sample_rate));
  s->max_frames = std::max<std::size_t>(s->max_frames, 1);
  s->min_frames =
      std::min(s->max_frames,
               static_cast<std::size_t>(std::llround(config_.min_seconds * config_.sample_rate)));
  // Room for 4 s (or the whole recording, when shorter): the drain thread empties it every 5 ms, so
  // only a stalled process drops frames.
  const std::size_t ring_frames =
      std::min<std::size_t>(s->max_frames, 4 * static_cast<std::size_t>(config_.sample_rate));
  s->ring.assign(ring_frames * static_cast<std::size_t>(config_.channels), 0.0f);
  s->clip.reserve(
      std::min<std::size_t>(s->max_frames, 10 * static_cast<std::size_t>(config_.sample_rate)) *
      static_cast<std::size_t>(config_.channels));

  const PaStreamParameters p = stream_parameters(device_, config_);
  PaError err = Pa_OpenStream(&s->pa, &p, nullptr, config_.sample_rate,
                              static_cast<unsigned long>(config_.frames_per_buffer), paNoFlag,
                              &Stream::on_audio, s.get());
  if (err != paNoError)
    throw TransientError(fmt::format("cannot open input device [{}] '{}' for '{}': {}",
                                     device_.index, device_.name, action, Pa_GetErrorText(err)));
  Pa_SetStreamFinishedCallback(s->pa, &Stream::on_finished);
  s->drainer = std::thread([raw = s.get()] { raw->drain_loop(); });
  s->started = std::chrono::steady_clock::now();
  err = Pa_StartStream(s->pa);
  if (err != paNoError) {
    {
      std::lock_guard lock(s->wake_mutex);
      s->stopping = true;
    }
    s->wake.notify_all();
    s->drainer.join();
    Pa_CloseStream(s->pa);
    throw TransientError(fmt::format("cannot start input device [{}] '{}' for '{}': {}",
                                     device_.index, device_.name, action, Pa_GetErrorText(err)));
  }
  spdlog::debug("capture: recording '{}' from [{}] '{}'", action, device_.index, device_.name);
  stream_ = std::move(s);
}

std::size_t PortAudioRecorder::frames_captured() const {
  return stream_ ? stream_->clip_frames.load(std::memory_order_acquire) : 0;
}

bool PortAudioRecorder::finished() const {
  return stream_ && (stream_->limit_reached.load(std::memory_order_acquire) ||
                     stream_->stream_ended.load(std::memory_order_acquire));
}

audio::AudioClip PortAudioRecorder::stop() {
  if (!stream_) throw std::logic_error("PortAudioRecorder::stop: no recording is running");
  std::unique_ptr<Stream> s = std::move(stream_);
  // Whether the stream ended on its own (not at the frame limit) must be read before we stop it,
  // because stopping it also runs the finished callback.
  const bool ended_by_itself = s->stream_ended.load(std::memory_order_acquire) &&
                               !s->limit_reached.load(std::memory_order_acquire);
  std::string stream_error;
  if (ended_by_itself || Pa_IsStreamActive(s->pa) < 0) {
    stream_error =
        fmt::format("the input stream of [{}] '{}' ended by itself (device disconnected or failed)",
                    device_.index, device_.name);
  }
  wait_for_minimum(*s);
  // Pa_StopStream waits for the last callback to return, so after it the ring is complete.
  const PaError stop_err = Pa_StopStream(s->pa);
  if (stop_err != paNoError && stream_error.empty()) {
    stream_error = fmt::format("stopping input device [{}] '{}' failed: {}", device_.index,
                               device_.name, Pa_GetErrorText(stop_err));
  }
  {
    std::lock_guard lock(s->wake_mutex);
    s->stopping = true;
  }
  s->wake.notify_all();
  s->drainer.join();
  Pa_CloseStream(s->pa);

  audio::AudioClip clip;
  clip.sample_rate = config_.sample_rate;
  clip.channels = config_.channels;
  clip.samples = std::move(s->clip);
  report_.frames = clip.frames();
  report_.overflow_callbacks = s->overflow_callbacks.load();
  report_.dropped_frames = s->dropped_frames.load();
  report_.limit_reached = s->limit_reached.load();
  report_.stream_error = stream_error;

  if (report_.overflow_callbacks > 0)
    spdlog::warn(
        "capture: the sound card overflowed in {} callbacks (samples were lost before PortAudio "
        "saw them)",
        report_.overflow_callbacks);
  if (report_.dropped_frames > 0)
    spdlog::warn("capture: {} frames dropped because the process fell behind the sound card",
                 report_.dropped_frames);
  if (report_.limit_reached)
    spdlog::info("capture: the recording reached its limit of {} s and stopped growing",
                 config_.max_seconds);
  if (!stream_error.empty()) {
    if (clip.samples.empty()) throw TransientError(stream_error + "; nothing was recorded");
    spdlog::error("capture: {}; keeping the {:.3f} s recorded before", stream_error,
                  clip.duration_seconds());
  }
  return clip;
}

}  // namespace echoplan::robot
