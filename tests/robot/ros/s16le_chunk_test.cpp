// Decoding audio_common_msgs/AudioData chunks (robot/ros/s16le_chunk.h): no ROS master needed.
#include "robot/ros/s16le_chunk.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace echoplan::robot {
namespace {

TEST(AppendS16le, ReadsLittleEndianSignedSamplesOver32768) {
  const std::uint8_t bytes[] = {0x00, 0x80, 0xff, 0x7f, 0x01, 0x00, 0xff, 0xff, 0x00, 0x00};
  std::vector<float> samples{0.5f};
  append_s16le(bytes, 5, samples);
  const std::vector<float> expected{0.5f,         -1.0f,         32767.0f / 32768,
                                    1.0f / 32768, -1.0f / 32768, 0.0f};
  EXPECT_EQ(samples, expected);
}

TEST(AppendS16leChunk, AppendsWholeFramesAndDropsAChunkThatIsNot) {
  const std::vector<std::uint8_t> two_stereo_frames{0x00, 0x40, 0x00, 0xc0, 0x01, 0x00, 0xff, 0xff};
  std::vector<float> samples;
  ChunkOutcome outcome = append_s16le_chunk(two_stereo_frames, 2, 10, samples);
  EXPECT_FALSE(outcome.misaligned);
  EXPECT_FALSE(outcome.limit_reached);
  EXPECT_EQ(samples, (std::vector<float>{0.5f, -0.5f, 1.0f / 32768, -1.0f / 32768}));
  // 6 bytes are 1.5 stereo frames: dropped whole, the clip unchanged.
  outcome = append_s16le_chunk({two_stereo_frames.data(), 6}, 2, 10, samples);
  EXPECT_TRUE(outcome.misaligned);
  EXPECT_EQ(samples.size(), 4u);
}

TEST(AppendS16leChunk, StopsAtMaxFramesExactly) {
  const std::vector<std::uint8_t> three_mono_frames{0x00, 0x40, 0x00, 0x20, 0x00, 0x10};
  std::vector<float> samples;
  EXPECT_FALSE(append_s16le_chunk(three_mono_frames, 1, 4, samples).limit_reached);
  const ChunkOutcome outcome = append_s16le_chunk(three_mono_frames, 1, 4, samples);
  EXPECT_TRUE(outcome.limit_reached);
  EXPECT_EQ(samples, (std::vector<float>{0.5f, 0.25f, 0.125f, 0.5f}));
}

}  // namespace
}  // namespace echoplan::robot
