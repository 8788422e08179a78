// The spectrogram grid (CY101's audio features) against an independent reference: the dataset's
// computation written out here with a direct DFT (no FFT, no shared code), on a constructed clip.
#include "perception/spectrogram_grid.h"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>

#include "common/error.h"

namespace echoplan::perception {
namespace {

// 0.6 s at 16 kHz: a 1 kHz tone for the first half, then one at 3 kHz, each at half scale.
ClipAnalysis two_tones() {
  ClipAnalysis clip;
  clip.sample_rate = 16000;
  for (int n = 0; n < 9600; ++n) {
    const double f = n < 4800 ? 1000.0 : 3000.0;
    clip.mono.push_back(static_cast<float>(0.5 * std::sin(2 * std::numbers::pi * f * n / 16000)));
  }
  return clip;
}

// The dataset's code at 16 kHz: 410-sample Hamming frames every 160 samples, the last zero-padded,
// a 512-point DFT of 16-bit integer samples, ln of the power floored at 0, bins 0..128, then 10 x
// 10 block means (12 bins and floor(frames / 10) frames a block), time bin by time bin.
std::vector<double> reference(const std::vector<float>& mono) {
  const int frame = 410, hop = 160, nfft = 512, kept = 129;
  const int frames =
      1 + static_cast<int>(std::ceil((static_cast<double>(mono.size()) - frame) / hop));
  std::vector<std::vector<double>> log_power(static_cast<std::size_t>(frames));
  for (int t = 0; t < frames; ++t)
    for (int k = 0; k < kept; ++k) {
      std::complex<double> x = 0;
      for (int n = 0; n < frame; ++n) {
        const std::size_t i = static_cast<std::size_t>(t * hop + n);
        const double sample = i < mono.size() ? 32768.0 * mono[i] : 0.0;
        const double w = 0.54 - 0.46 * std::cos(2 * std::numbers::pi * n / (frame - 1));
        x += sample * w * std::polar(1.0, -2 * std::numbers::pi * k * n / nfft);
      }
      log_power[static_cast<std::size_t>(t)].push_back(std::max(std::log(std::norm(x)), 0.0));
    }
  std::vector<double> grid;
  const int t_len = frames / 10, f_len = kept / 10;
  for (int tb = 0; tb < 10; ++tb)
    for (int fb = 0; fb < 10; ++fb) {
      double sum = 0;
      for (int t = tb * t_len; t < (tb + 1) * t_len; ++t)
        for (int k = fb * f_len; k < (fb + 1) * f_len; ++k)
          sum += log_power[static_cast<std::size_t>(t)][static_cast<std::size_t>(k)];
      grid.push_back(sum / (t_len * f_len));
    }
  return grid;
}

TEST(SpectrogramGrid, IsTheDatasetsComputationOnAConstructedClip) {
  const ClipAnalysis clip = two_tones();
  const std::vector<double> got = spectrogram_grid(clip);
  const std::vector<double> want = reference(clip.mono);
  ASSERT_EQ(got.size(), 100u);
  // KISS FFT computes in float32: a few parts in a million of each log power.
  for (std::size_t i = 0; i < got.size(); ++i) EXPECT_NEAR(got[i], want[i], 1e-3) << "entry " << i;
}

// Where the tones are: 1 kHz is bin 32 (block 2 of 12-bin blocks) in the first half of the clip,
// 3 kHz bin 96 (block 8) in the second; time bin by time bin, entry 10 t + f.
TEST(SpectrogramGrid, EachToneIsLoudestInItsBlockAndHalf) {
  const std::vector<double> grid = spectrogram_grid(two_tones());
  auto loudest = [&](int t) {
    const auto row = grid.begin() + 10 * t;
    return static_cast<int>(std::max_element(row, row + 10) - row);
  };
  for (int t = 0; t < 4; ++t) EXPECT_EQ(loudest(t), 2) << "time bin " << t;
  for (int t = 6; t < 10; ++t) EXPECT_EQ(loudest(t), 8) << "time bin " << t;
  EXPECT_EQ(spectrogram_grid_names()[12], "t2_f3");
}

TEST(SpectrogramGrid, SilenceIsZeroAndATooShortClipIsRefused) {
  ClipAnalysis silent;
  silent.sample_rate = 16000;
  silent.mono.assign(16000, 0.0f);
  for (double v : spectrogram_grid(silent)) EXPECT_EQ(v, 0.0);
  ClipAnalysis short_clip;
  short_clip.sample_rate = 16000;
  short_clip.mono.assign(1000, 0.1f);  // 5 frames
  EXPECT_THROW(spectrogram_grid(short_clip), InputError);
}

}  // namespace
}  // namespace echoplan::perception
