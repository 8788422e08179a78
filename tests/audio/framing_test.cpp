// Frame counts and padding of the librosa and python_speech_features conventions.
#include "audio/framing.h"

#include <gtest/gtest.h>

#include <cmath>

namespace echoplan::audio {
namespace {

TEST(Framing, CountsFollowLibrosaAndPsfConventions) {
  const FramingConfig centred{.frame_length = 2048, .hop = 512, .center = true};
  EXPECT_EQ(frame_count(centred, 22050),
            1u + 22050u / 512u);  // librosa: 1 + len // hop for even frames
  EXPECT_EQ(frame_count(centred, 1), 1u);
  EXPECT_EQ(frame_count(centred, 0), 0u);
  const FramingConfig psf{.frame_length = 551, .hop = 221, .center = false, .pad_tail = true};
  EXPECT_EQ(frame_count(psf, 22050), 99u);  // 1 + ceil((22050 - 551) / 221)
  EXPECT_EQ(frame_count(psf, 10), 1u);
  FramingConfig whole = psf;
  whole.pad_tail = false;
  EXPECT_EQ(frame_count(whole, 10), 0u);
  EXPECT_EQ(frame_count(whole, 551 + 221), 2u);
}

TEST(Framing, PadsWithZerosOrEdgeSamples) {
  const std::vector<float> x{1, 2, 3, 4, 5};
  std::vector<float> frame(4);
  FramingConfig zeros{.frame_length = 4, .hop = 2, .center = true, .center_pad = PadMode::zeros};
  copy_frame(zeros, x, 0, frame);
  EXPECT_EQ(frame, (std::vector<float>{0, 0, 1, 2}));
  FramingConfig edge = zeros;
  edge.center_pad = PadMode::edge;
  copy_frame(edge, x, 0, frame);
  EXPECT_EQ(frame, (std::vector<float>{1, 1, 1, 2}));
  copy_frame(edge, x, 2, frame);
  EXPECT_EQ(frame, (std::vector<float>{3, 4, 5, 5}));
  FramingConfig tail{.frame_length = 4, .hop = 3, .center = false, .pad_tail = true};
  copy_frame(tail, x, 1, frame);
  EXPECT_EQ(frame, (std::vector<float>{4, 5, 0, 0}));
}

}  // namespace
}  // namespace echoplan::audio
