// The feature extractor: documented floors for silence, short and empty signals, reuse, and
// spectral-shape features of tones against closed forms.
#include "audio/features.h"

#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>

#include "test_signals.h"

namespace echoplan::audio {
namespace {

using testing::input_error_message;
using testing::noise;
using testing::tone;

TEST(FeatureExtractor, SilenceGivesDocumentedFloors) {
  const std::vector<float> silence(8000, 0.0f);
  Features f;
  FeatureExtractor psf(psf_preset(16000));
  psf.compute(silence, f);
  for (float v : f.log_mel.values) EXPECT_FLOAT_EQ(v, std::log(DBL_EPSILON));
  for (std::size_t t = 0; t < f.mfcc.rows; ++t)
    EXPECT_FLOAT_EQ(f.mfcc.at(t, 0), std::log(DBL_EPSILON));
  FeatureExtractor lib(librosa_preset(16000));
  lib.compute(silence, f);
  for (float v : f.log_mel.values) EXPECT_FLOAT_EQ(v, -100.0f);
  for (std::size_t t = 0; t < f.centroid.rows; ++t) {
    EXPECT_EQ(f.centroid.at(t, 0), 0.0f);
    EXPECT_EQ(f.bandwidth.at(t, 0), 0.0f);
    EXPECT_EQ(f.rolloff.at(t, 0), 0.0f);
    EXPECT_FLOAT_EQ(f.flatness.at(t, 0), 1.0f);
    EXPECT_EQ(f.rms.at(t, 0), 0.0f);
    EXPECT_EQ(f.flux.at(t, 0), 0.0f);
  }
  for (float z : f.zcr.values) EXPECT_EQ(z, 0.0f);
}

TEST(FeatureExtractor, ShortAndEmptySignals) {
  // Shorter than one frame: both presets pad (psf's tail, librosa's centring) and give one frame.
  const auto x = tone(16000, 440.0, 100);
  Features f;
  FeatureExtractor psf(psf_preset(16000));
  psf.compute(x, f);
  EXPECT_EQ(f.mfcc.rows, 1u);
  FeatureExtractor lib(librosa_preset(16000));
  lib.compute(x, f);
  EXPECT_EQ(f.mfcc.rows, 1u);
  // A start-aligned framing without tail padding cannot frame it: an error that says so.
  FeatureConfig strict = psf_preset(16000);
  strict.stft.framing.pad_tail = false;
  FeatureExtractor whole(strict);
  EXPECT_NE(input_error_message([&] {
              whole.compute(x, f);
            }).find("shorter than one frame (400 samples)"),
            std::string::npos);
  EXPECT_NE(input_error_message([&] { lib.compute({}, f); }).find("empty signal"),
            std::string::npos);
  EXPECT_NE(input_error_message([] { global_features({}, 16000); }).find("empty signal"),
            std::string::npos);
}

TEST(FeatureExtractor, ReuseGivesIdenticalResults) {
  const auto a = noise(20000, 1);
  const auto b = noise(7000, 2);
  FeatureExtractor extractor(librosa_preset(22050));
  Features first, reused, again;
  extractor.compute(a, first);
  extractor.compute(b, reused);
  extractor.compute(a, reused);
  EXPECT_EQ(first.mfcc.values, reused.mfcc.values);
  EXPECT_EQ(first.flux.values, reused.flux.values);
  FeatureExtractor fresh(librosa_preset(22050));
  fresh.compute(a, again);
  EXPECT_EQ(first.log_mel.values, again.log_mel.values);
}

TEST(FeatureExtractor, ToneAtABinHasItsFrequencyAsCentroidAndRolloff) {
  // 2048-point Hann at 22050 Hz: bin 100 is 1076.66 Hz. Hann's main lobe is symmetric about the
  // bin, so the centroid sits on it up to the (tiny) leakage of the negative-frequency image: 0.5
  // Hz.
  const double hz = 100.0 * 22050.0 / 2048.0;
  Features f;
  FeatureExtractor extractor(librosa_preset(22050));
  extractor.compute(tone(22050, hz, 22050), f);
  const std::size_t t = f.centroid.rows / 2;
  EXPECT_NEAR(f.centroid.at(t, 0), hz, 0.5);
  // Magnitudes 0.25, 0.5, 0.25 around the bin: 85 % of the mass is reached at bin 101.
  EXPECT_NEAR(f.rolloff.at(t, 0), 101.0 * 22050.0 / 2048.0, 1e-3);
  EXPECT_LT(f.flatness.at(t, 0), 1e-3);
  EXPECT_NEAR(f.rms.at(t, 0), 0.5 / std::sqrt(2.0),
              1e-3);  // sine RMS; 2048 samples hold 100 whole periods
  // Uniform white noise is spectrally flat: flatness of |X|^2 of Gaussian-like noise is near
  // e^-gamma ~ 0.56.
  extractor.compute(noise(22050, 3), f);
  EXPECT_GT(f.flatness.at(t, 0), 0.4);
}

TEST(FeatureExtractor, TwoTonesHaveTheirMidpointAsCentroidAndHalfTheirSpacingAsBandwidth) {
  // Equal tones on bins 100 and 300 (Hann lobes 0.25/0.5/0.25): centroid bin 200, bandwidth
  // sqrt(100^2 + 0.5) bins. A tone's own bandwidth is not tested: float32 rounding leaves a
  // magnitude floor ~1e-7 of the peak in every bin, which at distances up to sr/2 dominates a 3-bin
  // lobe's spread; with 100-bin spacing it changes the result by < 0.1 %, the tolerance below.
  const double df = 22050.0 / 2048.0;
  auto x = tone(22050, 100 * df, 22050, 0.3);
  const auto y = tone(22050, 300 * df, 22050, 0.3);
  for (std::size_t i = 0; i < x.size(); ++i) x[i] += y[i];
  Features f;
  FeatureExtractor extractor(librosa_preset(22050));
  extractor.compute(x, f);
  const std::size_t t = f.centroid.rows / 2;
  EXPECT_NEAR(f.centroid.at(t, 0), 200 * df, 1e-3 * 200 * df);
  EXPECT_NEAR(f.bandwidth.at(t, 0), std::sqrt(100.0 * 100.0 + 0.5) * df, 1e-3 * 100 * df);
}

}  // namespace
}  // namespace echoplan::audio
