// Unit tests of windows, framing, STFT, mel filterbanks, extractor configuration, edge cases (silence,
// short and empty signals) and spectral-shape features, against closed forms and a direct DFT.
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <complex>
#include <numbers>

#include "audio/features.h"
#include "audio/framing.h"
#include "audio/mel.h"
#include "audio/stft.h"
#include "audio/window.h"
#include "common/error.h"
#include "common/rng.h"

namespace echoplan::audio {
namespace {

constexpr double kPi = std::numbers::pi;

std::vector<float> tone(int rate, double hz, std::size_t n, double amplitude = 0.5) {
  std::vector<float> x(n);
  for (std::size_t i = 0; i < n; ++i) x[i] = static_cast<float>(amplitude * std::sin(2 * kPi * hz * static_cast<double>(i) / rate));
  return x;
}

std::vector<float> noise(std::size_t n, std::uint64_t seed) {
  Rng rng(seed);
  std::vector<float> x(n);
  for (float& v : x) v = static_cast<float>(uniform01(rng) - 0.5);
  return x;
}

template <typename Fn>
std::string input_error_message(Fn fn) {
  try {
    fn();
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no InputError)";
}

TEST(Window, MatchesNumpyClosedForms) {
  // numpy.hanning(5) = [0, .5, 1, .5, 0]; scipy hann(4, sym=False) = [0, .5, 1, .5]; numpy.hamming(3) = [.08, 1, .08].
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
  EXPECT_NE(input_error_message([] { window_from_name("blackman"); }).find("unknown window 'blackman'"), std::string::npos);
}

TEST(Framing, CountsFollowLibrosaAndPsfConventions) {
  const FramingConfig centred{.frame_length = 2048, .hop = 512, .center = true};
  EXPECT_EQ(frame_count(centred, 22050), 1u + 22050u / 512u);  // librosa: 1 + len // hop for even frames
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

TEST(Stft, PowerMatchesADirectDoubleDft) {
  // Independent reference: an O(N^2) DFT in double of the same windowed, zero-padded frame. Tolerance:
  // float32 FFT error ~6e-8 * log2(N) relative to the frame's total power; 1e-6 of it covers that.
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
        sum += static_cast<double>(frame[n]) * window[n] * std::polar(1.0, -2 * kPi * double(k * n) / 512.0);
      expected[k] = std::norm(sum);
      total += expected[k];
    }
    for (std::size_t k = 0; k < 257; ++k) EXPECT_NEAR(power.at(t, k), expected[k], 1e-6 * total) << t << "," << k;
  }
}

TEST(Stft, RejectsBadConfigurations) {
  EXPECT_NE(input_error_message([] { Stft(StftConfig{.framing = {.frame_length = 512}, .fft_size = 256}); }).find("smaller than frame_length"),
            std::string::npos);
  EXPECT_NE(input_error_message([] { Stft(StftConfig{.framing = {.frame_length = 5}, .fft_size = 7}); }).find("must be even"),
            std::string::npos);
  EXPECT_NE(input_error_message([] { Stft(StftConfig{.framing = {.frame_length = 5, .hop = 0}, .fft_size = 8}); }).find("hop 0"),
            std::string::npos);
}

TEST(Mel, ScalesHaveTheirDefiningPoints) {
  // HTK: 1000 Hz is ~1000 mel. 2595 log10(1 + f/700) is the seed's 1125 ln(1 + f/700) times a constant
  // (2595 / ln 10 / 1125), so both give the same filter edges in Hz.
  EXPECT_NEAR(hz_to_mel_htk(1000.0), 1000.0, 0.05);
  for (double hz : {100.0, 4000.0, 15000.0})
    EXPECT_NEAR(hz_to_mel_htk(hz) / (1125.0 * std::log(1.0 + hz / 700.0)), 2595.0 / std::log(10.0) / 1125.0, 1e-12);
  EXPECT_NEAR(mel_to_hz_htk(hz_to_mel_htk(1234.5)), 1234.5, 1e-9);
  // Slaney: linear to 15 mels at 1 kHz, then 27 mels per factor 6.4.
  EXPECT_DOUBLE_EQ(hz_to_mel_slaney(500.0), 7.5);
  EXPECT_DOUBLE_EQ(hz_to_mel_slaney(1000.0), 15.0);
  EXPECT_NEAR(hz_to_mel_slaney(6400.0), 42.0, 1e-12);
  EXPECT_NEAR(mel_to_hz_slaney(hz_to_mel_slaney(3210.0)), 3210.0, 1e-9);
}

TEST(Mel, FilterbanksHaveTheirConstructionsProperties) {
  // psf triangles peak at exactly 1; Slaney-normalised triangles have area ~1 (weights * bin width).
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
    EXPECT_NEAR(area, 1.0, 0.05) << m;  // discretised triangle area: bins are 3.9 Hz, triangles >= 50 Hz wide
  }
  EXPECT_NE(input_error_message([] { MelFilterbank({.n_mels = 10, .fmin_hz = 9000}, 16000, 512); }).find("mel range"),
            std::string::npos);
}

TEST(FeatureConfig, ValidationNamesTheParameterUnitAndRange) {
  FeatureConfig c = librosa_preset(44100);
  c.mel.n_mels = 0;
  EXPECT_NE(input_error_message([&] { FeatureExtractor{c}; }).find("parameter n_mels = 0"), std::string::npos);
  c = librosa_preset(44100);
  c.mel.fmax_hz = 30000;
  EXPECT_NE(input_error_message([&] { FeatureExtractor{c}; }).find("parameter fmax = 30000 Hz is outside 0..22050"), std::string::npos);
  c = psf_preset(16000);
  c.preemphasis = std::nan("");
  EXPECT_NE(input_error_message([&] { FeatureExtractor{c}; }).find("parameter preemphasis"), std::string::npos);
  c = psf_preset(16000);
  c.n_mfcc = 27;
  EXPECT_NE(input_error_message([&] { FeatureExtractor{c}; }).find("parameter n_mfcc = 27"), std::string::npos);
  c = psf_preset(16000);
  c.stft.fft_size = 256;  // frame is 400 samples
  EXPECT_NE(input_error_message([&] { FeatureExtractor{c}; }).find("parameter fft_size = 256 samples"), std::string::npos);
  EXPECT_NE(input_error_message([] { preset_by_name("htk", 16000); }).find("unknown feature preset 'htk'"), std::string::npos);
  EXPECT_EQ(describe_parameters(psf_preset(16000)).size(), 16u);
}

TEST(FeatureExtractor, SilenceGivesDocumentedFloors) {
  const std::vector<float> silence(8000, 0.0f);
  Features f;
  FeatureExtractor psf(psf_preset(16000));
  psf.compute(silence, f);
  for (float v : f.log_mel.values) EXPECT_FLOAT_EQ(v, std::log(DBL_EPSILON));
  for (std::size_t t = 0; t < f.mfcc.rows; ++t) EXPECT_FLOAT_EQ(f.mfcc.at(t, 0), std::log(DBL_EPSILON));
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
  EXPECT_NE(input_error_message([&] { whole.compute(x, f); }).find("shorter than one frame (400 samples)"), std::string::npos);
  EXPECT_NE(input_error_message([&] { lib.compute({}, f); }).find("empty signal"), std::string::npos);
  EXPECT_NE(input_error_message([] { global_features({}, 16000); }).find("empty signal"), std::string::npos);
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
  // 2048-point Hann at 22050 Hz: bin 100 is 1076.66 Hz. Hann's main lobe is symmetric about the bin, so the
  // centroid sits on it up to the (tiny) leakage of the negative-frequency image: 0.5 Hz.
  const double hz = 100.0 * 22050.0 / 2048.0;
  Features f;
  FeatureExtractor extractor(librosa_preset(22050));
  extractor.compute(tone(22050, hz, 22050), f);
  const std::size_t t = f.centroid.rows / 2;
  EXPECT_NEAR(f.centroid.at(t, 0), hz, 0.5);
  // Magnitudes 0.25, 0.5, 0.25 around the bin: 85 % of the mass is reached at bin 101.
  EXPECT_NEAR(f.rolloff.at(t, 0), 101.0 * 22050.0 / 2048.0, 1e-3);
  EXPECT_LT(f.flatness.at(t, 0), 1e-3);
  EXPECT_NEAR(f.rms.at(t, 0), 0.5 / std::sqrt(2.0), 1e-3);  // sine RMS; 2048 samples hold 100 whole periods
  // Uniform white noise is spectrally flat: flatness of |X|^2 of Gaussian-like noise is near e^-gamma ~ 0.56.
  extractor.compute(noise(22050, 3), f);
  EXPECT_GT(f.flatness.at(t, 0), 0.4);
}

TEST(FeatureExtractor, TwoTonesHaveTheirMidpointAsCentroidAndHalfTheirSpacingAsBandwidth) {
  // Equal tones on bins 100 and 300 (Hann lobes 0.25/0.5/0.25): centroid bin 200, bandwidth
  // sqrt(100^2 + 0.5) bins. A tone's own bandwidth is not tested: float32 rounding leaves a magnitude floor
  // ~1e-7 of the peak in every bin, which at distances up to sr/2 dominates a 3-bin lobe's spread; with
  // 100-bin spacing it changes the result by < 0.1 %, the tolerance below.
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

TEST(GlobalFeatures, ToneCentroidAndPrimeLengthFallback) {
  // A tone on an exact DFT bin: its whole-signal centroid is the tone frequency (plus leakage-free).
  const auto x = tone(8000, 1000.0, 8000);
  const GlobalFeatures g = global_features(x, 8000);
  EXPECT_NEAR(g.centroid_hz, 1000.0, 0.5);
  EXPECT_NEAR(g.rms, 0.5 / std::sqrt(2.0), 1e-6);
  EXPECT_EQ(g.zero_crossings, 1999);  // 2 per period over 1000 periods, minus the one at sample 0 (0 counts positive)
  // 1000003 is prime: the exact-length DFT would cost N^2, so the signal is zero-padded to a smooth length.
  // A Hann-windowed burst inside it has a smooth spectrum, so the padded DFT samples the same spectrum as
  // the burst's own DFT, only more finely: the centroids agree to the sampling difference (0.5 %).
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
