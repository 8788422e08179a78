// Whole-signal features: a tone's centroid, and the fallback for lengths with a large prime factor.
#include <gtest/gtest.h>

#include <cmath>

#include "audio/features.h"
#include "audio/window.h"
#include "test_signals.h"

namespace echoplan::audio {
namespace {

using testing::tone;

TEST(GlobalFeatures, ToneCentroidAndPrimeLengthFallback) {
  // A tone on an exact DFT bin: its whole-signal centroid is the tone frequency (plus
  // leakage-free).
  const auto x = tone(8000, 1000.0, 8000);
  const GlobalFeatures g = global_features(x, 8000);
  EXPECT_NEAR(g.centroid_hz, 1000.0, 0.5);
  EXPECT_NEAR(g.rms, 0.5 / std::sqrt(2.0), 1e-6);
  EXPECT_EQ(g.zero_crossings,
            1999);  // 2 per period over 1000 periods, minus the one at sample 0 (0 counts positive)
  // 1000003 is prime: the exact-length DFT would cost N^2, so the signal is zero-padded to a smooth
  // length. A Hann-windowed burst inside it has a smooth spectrum, so the padded DFT samples the
  // same spectrum as the burst's own DFT, only more finely: the centroids agree to the sampling
  // difference (0.5 %).
  std::vector<float> burst = tone(48000, 3000.0, 4800);
  const auto hann = make_window(WindowKind::hann_symmetric, 4800);
  for (std::size_t i = 0; i < burst.size(); ++i) burst[i] *= hann[i];
  std::vector<float> long_signal(1000003, 0.0f);
  std::copy(burst.begin(), burst.end(), long_signal.begin() + 500000);
  const double expected = global_features(burst, 48000).centroid_hz;
  EXPECT_NEAR(global_features(long_signal, 48000).centroid_hz, expected, 5e-3 * expected);
}

}  // namespace
}  // namespace echoplan::audio
