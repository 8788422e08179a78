#include "audio/framing.h"

#include <fmt/format.h>

#include <algorithm>

#include "common/error.h"

namespace echoplan::audio {

void validate_framing(const FramingConfig& config) {
  if (config.frame_length < 1)
    throw InputError(fmt::format("frame_length {} must be at least 1 sample", config.frame_length));
  if (config.hop < 1) throw InputError(fmt::format("hop {} must be at least 1 sample", config.hop));
}

std::size_t frame_count(const FramingConfig& config, std::size_t length) {
  if (length == 0) return 0;
  const auto frame = static_cast<std::size_t>(config.frame_length);
  const auto hop = static_cast<std::size_t>(config.hop);
  if (config.center) {
    const std::size_t padded = length + 2 * (frame / 2);
    return padded < frame ? 0 : 1 + (padded - frame) / hop;
  }
  if (length <= frame) return (length == frame || config.pad_tail) ? 1 : 0;
  const std::size_t rest = length - frame;
  return 1 + (config.pad_tail ? (rest + hop - 1) / hop : rest / hop);
}

void copy_frame(const FramingConfig& config, std::span<const float> signal, std::size_t index,
                std::span<float> out) {
  const auto length = static_cast<std::ptrdiff_t>(signal.size());
  const auto frame = static_cast<std::ptrdiff_t>(config.frame_length);
  // First sample of the frame in signal coordinates; negative or past the end means padding.
  std::ptrdiff_t start = static_cast<std::ptrdiff_t>(index) * config.hop;
  if (config.center) start -= frame / 2;
  const bool edge = config.center && config.center_pad == PadMode::edge;
  // Fast path: the frame lies wholly inside the signal.
  if (start >= 0 && start + frame <= length) {
    std::copy_n(signal.begin() + start, frame, out.begin());
    return;
  }
  for (std::ptrdiff_t n = 0; n < frame; ++n) {
    const std::ptrdiff_t i = start + n;
    float value = 0.0f;
    if (i >= 0 && i < length)
      value = signal[static_cast<std::size_t>(i)];
    else if (edge && length > 0)
      value = signal[static_cast<std::size_t>(std::clamp<std::ptrdiff_t>(i, 0, length - 1))];
    out[static_cast<std::size_t>(n)] = value;
  }
}

}  // namespace echoplan::audio
