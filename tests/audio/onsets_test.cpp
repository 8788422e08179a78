// Tests of onset detection and onset-aligned feature windows.
#include "audio/onsets.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "audio/features.h"
#include "common/error.h"

namespace echoplan::audio {
namespace {

FeatureMatrix column(const std::vector<float>& values) {
  FeatureMatrix m;
  m.resize(values.size(), 1);
  m.values = values;
  return m;
}

TEST(Onsets, PicksIsolatedPeaksAndHonoursWait) {
  std::vector<float> env(60, 0.01f);
  env[10] = 1.0f;
  env[13] = 0.9f;  // within `wait` of 10 and not a local max over +-3: ignored
  env[40] = 0.6f;
  const auto onsets = detect_onsets(column(env));
  EXPECT_EQ(onsets, (std::vector<std::size_t>{10, 40}));
  EXPECT_EQ(alignment_frame(column(env), OnsetChoice::first), 10u);
  env[10] = 0.5f;
  EXPECT_EQ(alignment_frame(column(env), OnsetChoice::strongest), 13u);
  EXPECT_EQ(detect_onsets(column(env), {.pre_max = 0, .post_max = 0, .wait = 0}),
            (std::vector<std::size_t>{10, 13, 40}));
}

TEST(Onsets, SilenceHasNoOnsetsAndAlignsOnFrameZero) {
  const FeatureMatrix flat = column(std::vector<float>(20, 0.0f));
  EXPECT_TRUE(detect_onsets(flat).empty());
  EXPECT_EQ(alignment_frame(flat, OnsetChoice::first), 0u);
  EXPECT_THROW(alignment_frame(FeatureMatrix{}, OnsetChoice::first), InputError);
  EXPECT_THROW(detect_onsets(flat, {.wait = -1}), InputError);
}

TEST(Onsets, FindsAnImpactInASignal) {
  // 0.5 s of silence then a decaying 800 Hz burst: the first onset is the burst's frame (librosa
  // framing, hop 512 at 22050 Hz, centred: sample 11025 is frame 21.5; the flux peaks at frame 22).
  std::vector<float> x(22050, 0.0f);
  for (std::size_t n = 11025; n < x.size(); ++n)
    x[n] = static_cast<float>(0.8 * std::exp(-double(n - 11025) / 2000.0) *
                              std::sin(2 * std::numbers::pi * 800.0 * double(n) / 22050.0));
  FeatureExtractor extractor(librosa_preset(22050));
  Features f;
  extractor.compute(x, f);
  const std::size_t onset = alignment_frame(f.flux, OnsetChoice::first);
  EXPECT_GE(onset, 21u);
  EXPECT_LE(onset, 22u);
}

TEST(Onsets, WindowHasFixedShapeAndRepeatsEdges) {
  FeatureMatrix m;
  m.resize(5, 2);
  for (std::size_t r = 0; r < 5; ++r) {
    m.at(r, 0) = float(r);
    m.at(r, 1) = float(10 * r);
  }
  const FeatureMatrix w = onset_window(m, 1, 3, 3);
  ASSERT_EQ(w.rows, 6u);
  ASSERT_EQ(w.cols, 2u);
  const std::vector<float> first_column{0, 0, 0, 1, 2, 3};
  for (std::size_t r = 0; r < 6; ++r) EXPECT_EQ(w.at(r, 0), first_column[r]);
  const FeatureMatrix tail = onset_window(m, 4, 1, 3);
  EXPECT_EQ(tail.at(3, 1), 40.0f);  // rows past the end repeat the last row
  EXPECT_THROW(onset_window(FeatureMatrix{}, 0, 1, 1), InputError);
}

}  // namespace
}  // namespace echoplan::audio
