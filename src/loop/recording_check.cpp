#include "loop/recording_check.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace echoplan::loop {

namespace {

constexpr float kSilentPeak = 1.0f / 32768.0f;  // one step of a 16-bit converter
constexpr float kFullScale = 0.999f;
constexpr double kMaxClippedShare = 0.01;
constexpr double kShortTolerance_s = 0.05;  // a device's start-up latency

StepFault skipped(std::string kind, std::string detail) {
  return {std::move(kind), std::move(detail), FaultEffect::observation_skipped};
}

std::optional<StepFault> check_levels(const audio::AudioClip& clip) {
  float peak = 0;
  std::size_t at_full_scale = 0;
  for (const float s : clip.samples) {
    const float a = std::fabs(s);
    peak = std::max(peak, a);
    if (a >= kFullScale) ++at_full_scale;
  }
  if (peak <= kSilentPeak)
    return skipped("recording silent",
                   fmt::format("peak {:g} over {} samples, nothing above one 16-bit step", peak,
                               clip.samples.size()));
  const double share =
      static_cast<double>(at_full_scale) / static_cast<double>(clip.samples.size());
  if (share > kMaxClippedShare)
    return skipped("recording clipped",
                   fmt::format("{:.1f}% of the samples at full scale (at most {:g}%); lower the "
                               "microphone's gain",
                               100 * share, 100 * kMaxClippedShare));
  return std::nullopt;
}

}  // namespace

std::optional<StepFault> check_recording(const audio::AudioClip& clip,
                                         const robot::ActionReport& report,
                                         const robot::CaptureReport& capture,
                                         const RecordingChecks& checks) {
  if (!capture.stream_error.empty())
    return skipped("capture device lost", fmt::format("{} ({} frames arrived before)",
                                                      capture.stream_error, clip.frames()));
  if (clip.frames() == 0) return skipped("recording empty", "the recorder returned no frames");
  if ((checks.sample_rate > 0 && clip.sample_rate != checks.sample_rate) ||
      (checks.channels > 0 && clip.channels != checks.channels))
    return skipped(
        "recording of another format",
        fmt::format("{} Hz, {} channel(s); the classifier expects {} Hz, {} channel(s)",
                    clip.sample_rate, clip.channels, checks.sample_rate, checks.channels));
  if (!checks.live) return std::nullopt;
  if (auto fault = check_levels(clip)) return fault;
  if (clip.duration_seconds() < report.duration_s - kShortTolerance_s)
    return skipped("recording shorter than the action",
                   fmt::format("{:.3f} s of sound for an action of {:.3f} s",
                               clip.duration_seconds(), report.duration_s));
  return std::nullopt;
}

}  // namespace echoplan::loop
