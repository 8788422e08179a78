// The STFT's power spectrum against a direct double-precision DFT; bad configurations rejected.
#include "audio/stft.h"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>

#include "audio/features.h"
#include "audio/framing.h"
#include "audio/window.h"
#include "test_signals.h"

namespace echoplan::audio {
namespace {

using testing::input_error_message;
using testing::noise;

constexpr double kPi = std::numbers::pi;

TEST(Stft, PowerMatchesADirectDoubleDft) {
  // Independent reference: an O(N^2) DFT in double of the same windowed, zero-padded frame.
  // Tolerance: float32 FFT error ~6e-8 * log2(N) relative to the frame's total power; 1e-6 of it
  // covers that.
  const auto x = noise(3000, 7);
  StftConfig config{.framing = {.frame_length = 400, .hop = 160, .center = false, .pad_tail = true},
                    .fft_size = 512,
                    .window = WindowKind::hamming_symmetric};
  Stft stft(config);
  FeatureMatrix power;
  stft.power(x, power);
  ASSERT_EQ(power.rows, frame_count(config.framing, x.size()));
  ASSERT_EQ(power.cols, 257u);
  const auto window = make_window(config.window, 400);
  for (std::size_t t : {std::size_t{0}, std::size_t{7}, power.rows - 1}) {
    std::vector<float> frame(400);
    copy_frame(config.framing, x, t, frame);
    double total = 0.0;
    std::vector<double> expected(257);
    for (std::size_t k = 0; k < 257; ++k) {
      std::complex<double> sum = 0.0;
      for (std::size_t n = 0; n < 400; ++n)
        sum += static_cast<double>(frame[n]) * window[n] *
               std::polar(1.0, -2 * kPi * double(k * n) / 512.0);
      expected[k] = std::norm(sum);
      total += expected[k];
    }
    for (std::size_t k = 0; k < 257; ++k)
      EXPECT_NEAR(power.at(t, k), expected[k], 1e-6 * total) << t << "," << k;
  }
}

TEST(Stft, RejectsBadConfigurations) {
  EXPECT_NE(input_error_message([] {
              Stft(StftConfig{.framing = {.frame_length = 512}, .fft_size = 256});
            }).find("smaller than frame_length"),
            std::string::npos);
  EXPECT_NE(input_error_message([] {
              Stft(StftConfig{.framing = {.frame_length = 5}, .fft_size = 7});
            }).find("must be even"),
            std::string::npos);
  EXPECT_NE(input_error_message([] {
              Stft(StftConfig{.framing = {.frame_length = 5, .hop = 0}, .fft_size = 8});
            }).find("hop 0"),
            std::string::npos);
}

}  // namespace
}  // namespace echoplan::audio
