#include "robot/ros/s16le_chunk.h"

#include <algorithm>

namespace echoplan::robot {

void append_s16le(const std::uint8_t* bytes, std::size_t count, std::vector<float>& samples) {
  samples.reserve(samples.size() + count);
  for (std::size_t i = 0; i < count; ++i) {
    // Assembled byte by byte, so the stream's byte order holds whatever the host's is.
    const auto value = static_cast<std::int16_t>(
        static_cast<std::uint16_t>(bytes[2 * i] | static_cast<unsigned>(bytes[2 * i + 1]) << 8));
    samples.push_back(static_cast<float>(value) / 32768.0f);
  }
}

ChunkOutcome append_s16le_chunk(std::span<const std::uint8_t> chunk, int channels,
                                std::size_t max_frames, std::vector<float>& samples) {
  const auto channel_count = static_cast<std::size_t>(channels);
  const std::size_t frame_bytes = 2 * channel_count;
  if (chunk.size() % frame_bytes != 0) return {.misaligned = true};
  const std::size_t have = samples.size() / channel_count;
  const std::size_t frames = std::min(chunk.size() / frame_bytes, max_frames - have);
  append_s16le(chunk.data(), frames * channel_count, samples);
  return {.limit_reached = have + frames >= max_frames};
}

}  // namespace echoplan::robot
