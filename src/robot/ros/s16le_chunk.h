// Decoding the chunks of raw S16LE audio that audio_common_msgs/AudioData carries: the part of
// AudioTopicRecorder that needs no ROS master, so that it is tested and fuzzed on its own.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace echoplan::robot {

// Appends the `count` S16LE samples at `bytes` (2 x count bytes) to `samples` as floats (value /
// 32768, as PortAudio and the WAV reader scale them, so every 16-bit value is kept exactly).
void append_s16le(const std::uint8_t* bytes, std::size_t count, std::vector<float>& samples);

// What append_s16le_chunk did with one chunk.
struct ChunkOutcome {
  bool misaligned = false;     // not a whole number of frames: nothing appended
  bool limit_reached = false;  // `samples` now holds `max_frames` frames
};

// Appends the frames of `chunk` (interleaved S16LE, `channels` >= 1 per frame) to `samples`
// (interleaved floats, a whole number of frames, at most `max_frames`), keeping only as many as fit
// in `max_frames` frames in all.
ChunkOutcome append_s16le_chunk(std::span<const std::uint8_t> chunk, int channels,
                                std::size_t max_frames, std::vector<float>& samples);

}  // namespace echoplan::robot
