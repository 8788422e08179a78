// Analysis windows against numpy's closed forms.
#include "audio/window.h"

#include <gtest/gtest.h>

#include <cmath>

#include "test_signals.h"

namespace echoplan::audio {
namespace {

using testing::input_error_message;

TEST(Window, MatchesNumpyClosedForms) {
  // numpy.hanning(5) = [0, .5, 1, .5, 0]; scipy hann(4, sym=False) = [0, .5, 1, .5];
  // numpy.hamming(3) = [.08, 1, .08].
  const auto hs = make_window(WindowKind::hann_symmetric, 5);
  const std::vector<float> hs_expected{0.0f, 0.5f, 1.0f, 0.5f, 0.0f};
  for (std::size_t i = 0; i < 5; ++i) EXPECT_NEAR(hs[i], hs_expected[i], 1e-7);
  const auto hp = make_window(WindowKind::hann_periodic, 4);
  const std::vector<float> hp_expected{0.0f, 0.5f, 1.0f, 0.5f};
  for (std::size_t i = 0; i < 4; ++i) EXPECT_NEAR(hp[i], hp_expected[i], 1e-7);
  const auto hm = make_window(WindowKind::hamming_symmetric, 3);
  EXPECT_NEAR(hm[0], 0.08, 1e-7);
  EXPECT_NEAR(hm[1], 1.0, 1e-7);
  EXPECT_NEAR(make_window(WindowKind::hamming_periodic, 4)[2], 1.0, 1e-7);
  EXPECT_EQ(make_window(WindowKind::rectangular, 3), (std::vector<float>{1, 1, 1}));
  EXPECT_EQ(window_from_name("hann"), WindowKind::hann_periodic);
  EXPECT_EQ(window_name(WindowKind::hamming_symmetric), "hamming_symmetric");
  EXPECT_NE(
      input_error_message([] { window_from_name("blackman"); }).find("unknown window 'blackman'"),
      std::string::npos);
}

}  // namespace
}  // namespace echoplan::audio
