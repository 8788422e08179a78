// Mel scales at their defining points and the properties of each filterbank construction.
#include "audio/mel.h"

#include <gtest/gtest.h>

#include <cmath>

#include "test_signals.h"

namespace echoplan::audio {
namespace {

using testing::input_error_message;

TEST(Mel, ScalesHaveTheirDefiningPoints) {
  // HTK: 1000 Hz is ~1000 mel. 2595 log10(1 + f/700) is the report's 1125 ln(1 + f/700) times a
  // constant (2595 / ln 10 / 1125), so both give the same filter edges in Hz.
  EXPECT_NEAR(hz_to_mel_htk(1000.0), 1000.0, 0.05);
  for (double hz : {100.0, 4000.0, 15000.0})
    EXPECT_NEAR(hz_to_mel_htk(hz) / (1125.0 * std::log(1.0 + hz / 700.0)),
                2595.0 / std::log(10.0) / 1125.0, 1e-12);
  EXPECT_NEAR(mel_to_hz_htk(hz_to_mel_htk(1234.5)), 1234.5, 1e-9);
  // Slaney: linear to 15 mels at 1 kHz, then 27 mels per factor 6.4.
  EXPECT_DOUBLE_EQ(hz_to_mel_slaney(500.0), 7.5);
  EXPECT_DOUBLE_EQ(hz_to_mel_slaney(1000.0), 15.0);
  EXPECT_NEAR(hz_to_mel_slaney(6400.0), 42.0, 1e-12);
  EXPECT_NEAR(mel_to_hz_slaney(hz_to_mel_slaney(3210.0)), 3210.0, 1e-9);
}

TEST(Mel, FilterbanksHaveTheirConstructionsProperties) {
  // psf triangles peak at exactly 1; Slaney-normalised triangles have area ~1 (weights * bin
  // width).
  const MelFilterbank psf({.style = MelFilterStyle::psf_bins, .n_mels = 26}, 16000, 512);
  for (std::size_t m = 0; m < psf.filters(); ++m) {
    double peak = 0.0;
    for (std::size_t k = 0; k < psf.bins(); ++k) peak = std::max(peak, psf.weight(m, k));
    EXPECT_DOUBLE_EQ(peak, 1.0) << m;
  }
  const MelFilterbank slaney({.style = MelFilterStyle::slaney, .n_mels = 40}, 16000, 4096);
  for (std::size_t m = 0; m < slaney.filters(); ++m) {
    double area = 0.0;
    for (std::size_t k = 0; k < slaney.bins(); ++k) area += slaney.weight(m, k) * 16000.0 / 4096.0;
    EXPECT_NEAR(area, 1.0, 0.05)
        << m;  // discretised triangle area: bins are 3.9 Hz, triangles >= 50 Hz wide
  }
  EXPECT_NE(input_error_message([] {
              MelFilterbank({.n_mels = 10, .fmin_hz = 9000}, 16000, 512);
            }).find("mel range"),
            std::string::npos);
}

}  // namespace
}  // namespace echoplan::audio
