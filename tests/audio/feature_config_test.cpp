// Feature configuration: the presets' documented parameters, and validation messages naming the
// parameter, its unit and its range.
#include <gtest/gtest.h>

#include <cmath>

#include "audio/features.h"
#include "test_signals.h"

namespace echoplan::audio {
namespace {

using testing::input_error_message;

TEST(FeatureConfig, ValidationNamesTheParameterUnitAndRange) {
  FeatureConfig c = librosa_preset(44100);
  c.mel.n_mels = 0;
  EXPECT_NE(input_error_message([&] { FeatureExtractor{c}; }).find("parameter n_mels = 0"),
            std::string::npos);
  c = librosa_preset(44100);
  c.mel.fmax_hz = 30000;
  EXPECT_NE(input_error_message([&] {
              FeatureExtractor{c};
            }).find("parameter fmax = 30000 Hz is outside 0..22050"),
            std::string::npos);
  c = librosa_preset(16000);
  c.amin = 1e-30;  // flatness's products of 16 powers would underflow
  EXPECT_NE(input_error_message([&] {
              FeatureExtractor{c};
            }).find("parameter amin = 1e-30 power is outside 1e-18..1"),
            std::string::npos);
  c = psf_preset(16000);
  c.preemphasis = std::nan("");
  EXPECT_NE(input_error_message([&] { FeatureExtractor{c}; }).find("parameter preemphasis"),
            std::string::npos);
  c = psf_preset(16000);
  c.n_mfcc = 27;
  EXPECT_NE(input_error_message([&] { FeatureExtractor{c}; }).find("parameter n_mfcc = 27"),
            std::string::npos);
  c = psf_preset(16000);
  c.stft.fft_size = 256;  // frame is 400 samples
  EXPECT_NE(
      input_error_message([&] { FeatureExtractor{c}; }).find("parameter fft_size = 256 samples"),
      std::string::npos);
  EXPECT_NE(input_error_message([] {
              preset_by_name("htk", 16000);
            }).find("unknown feature preset 'htk'"),
            std::string::npos);
  EXPECT_EQ(describe_parameters(psf_preset(16000)).size(), 16u);
}

// python_speech_features 0.6.1: 25 ms frames every 10 ms (rounded half up), FFT the next power of
// two, 26 filters, 13 cepstra, lifter 22, pre-emphasis 0.97.
TEST(FeatureConfig, PsfPresetHasTheLibraryDefaults) {
  const FeatureConfig c = psf_preset(16000);
  EXPECT_EQ(c.stft.framing.frame_length, 400);
  EXPECT_EQ(c.stft.framing.hop, 160);
  EXPECT_EQ(c.stft.fft_size, 512);
  EXPECT_FALSE(c.stft.framing.center);
  EXPECT_EQ(c.mel.n_mels, 26);
  EXPECT_EQ(c.n_mfcc, 13);
  EXPECT_EQ(c.lifter, 22);
  EXPECT_DOUBLE_EQ(c.preemphasis, 0.97);
  EXPECT_EQ(c.log_scale, LogScale::natural_log);
  // 22050 Hz: 551.25 -> 551 samples, 220.5 -> 221 (half up), FFT 1024.
  const FeatureConfig d = psf_preset(22050);
  EXPECT_EQ(d.stft.framing.frame_length, 551);
  EXPECT_EQ(d.stft.framing.hop, 221);
  EXPECT_EQ(d.stft.fft_size, 1024);
}

// librosa 0.11: n_fft 2048, hop 512, centred frames, 128 Slaney mels, 20 cepstra, dB with top_db
// 80; the zero-crossing rate pads with edge samples.
TEST(FeatureConfig, LibrosaPresetHasTheLibraryDefaults) {
  const FeatureConfig c = librosa_preset(44100);
  EXPECT_EQ(c.stft.framing.frame_length, 2048);
  EXPECT_EQ(c.stft.framing.hop, 512);
  EXPECT_TRUE(c.stft.framing.center);
  EXPECT_EQ(c.mel.n_mels, 128);
  EXPECT_EQ(c.n_mfcc, 20);
  EXPECT_EQ(c.lifter, 0);
  EXPECT_EQ(c.log_scale, LogScale::decibel);
  EXPECT_DOUBLE_EQ(c.top_db, 80.0);
  EXPECT_EQ(c.zcr_framing.center_pad, PadMode::edge);
  EXPECT_EQ(preset_by_name("librosa", 44100).stft.framing.hop, 512);
  EXPECT_EQ(preset_by_name("psf", 16000).stft.framing.hop, 160);
}

}  // namespace
}  // namespace echoplan::audio
