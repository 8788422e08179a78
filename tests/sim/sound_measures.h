// Test helpers shared by the sound tests: what a rendered clip sounds like, measured with the
// project's own audio code (audio/stft.h, audio/framing.h, audio/features.h, audio/onsets.h), so
// the tests check the sound, not the formula that made it.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "audio/clip.h"
#include "audio/features.h"
#include "audio/framing.h"
#include "audio/onsets.h"
#include "audio/stft.h"

namespace echoplan::sim {

// One channel of an interleaved clip.
inline std::vector<float> channel_of(const audio::AudioClip& clip, int channel) {
  std::vector<float> x(clip.frames());
  for (std::size_t i = 0; i < x.size(); ++i)
    x[i] = clip.samples[i * static_cast<std::size_t>(clip.channels) + channel];
  return x;
}

// Magnitude spectrum of `count` samples of `x` from `start` (past the end: zeros), Hann-windowed
// (symmetric) and zero-padded to a power of two >= pad * count: bins of rate / nfft Hz.
inline std::vector<double> magnitude_spectrum(const std::vector<float>& x, int rate,
                                              std::size_t start, std::size_t count, double* bin_hz,
                                              std::size_t pad = 4) {
  std::size_t nfft = 2;
  while (nfft < pad * count) nfft *= 2;
  audio::StftConfig config;
  config.framing.frame_length = static_cast<int>(count);
  config.framing.hop = static_cast<int>(count);
  config.framing.center = false;
  config.fft_size = static_cast<int>(nfft);
  config.window = audio::WindowKind::hann_symmetric;
  audio::Stft stft(config);
  std::vector<float> frame(count, 0.0f);
  for (std::size_t i = 0; i < count && start + i < x.size(); ++i) frame[i] = x[start + i];
  std::vector<float> power(static_cast<std::size_t>(stft.bins()));
  stft.frame_power(frame, power);
  std::vector<double> mag(power.size());
  for (std::size_t k = 0; k < mag.size(); ++k) mag[k] = std::sqrt(static_cast<double>(power[k]));
  *bin_hz = static_cast<double>(rate) / static_cast<double>(nfft);
  return mag;
}

// RMS level (dB re full scale) of consecutive, non-overlapping frames of `frame_s` seconds.
inline std::vector<double> frame_levels_db(const std::vector<float>& x, int rate, double frame_s) {
  audio::FramingConfig framing;
  framing.frame_length = static_cast<int>(std::lround(frame_s * rate));
  framing.hop = framing.frame_length;
  framing.center = false;
  std::vector<float> frame(static_cast<std::size_t>(framing.frame_length));
  std::vector<double> levels;
  for (std::size_t t = 0; t < audio::frame_count(framing, x.size()); ++t) {
    audio::copy_frame(framing, x, t, frame);
    double energy = 0;
    for (float v : frame) energy += static_cast<double>(v) * v;
    levels.push_back(10 * std::log10(energy / static_cast<double>(frame.size()) + 1e-30));
  }
  return levels;
}

// Times (s) of the onsets the project's detector finds in `x` (librosa preset: spectral flux over
// 2048-sample frames, 512 apart).
inline std::vector<double> onset_times(const std::vector<float>& x, int rate) {
  audio::FeatureExtractor extractor(audio::librosa_preset(rate));
  audio::Features features;
  extractor.compute(x, features);
  std::vector<double> times;
  const double hop = extractor.config().stft.framing.hop;
  for (std::size_t frame : audio::detect_onsets(features.flux))
    times.push_back(static_cast<double>(frame) * hop / rate);
  return times;
}

}  // namespace echoplan::sim
