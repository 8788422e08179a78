#include "perception/spectrogram_grid.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "audio/stft.h"
#include "common/error.h"

namespace echoplan::perception {

namespace {

// The original's frame and hop at 16 kHz, as durations.
constexpr double kFrameSeconds = 410.0 / 16000.0;
constexpr double kHopSeconds = 160.0 / 16000.0;

audio::StftConfig grid_stft(int sample_rate) {
  audio::StftConfig c;
  c.framing.frame_length = std::max(1, static_cast<int>(std::lround(kFrameSeconds * sample_rate)));
  c.framing.hop = std::max(1, static_cast<int>(std::lround(kHopSeconds * sample_rate)));
  c.framing.center = false;
  c.framing.pad_tail = true;
  c.fft_size = 2;
  while (c.fft_size < c.framing.frame_length) c.fft_size *= 2;
  c.window = audio::WindowKind::hamming_symmetric;
  return c;
}

}  // namespace

std::vector<double> spectrogram_grid(const ClipAnalysis& clip) {
  audio::Stft stft(grid_stft(clip.sample_rate));
  // 16-bit integer scale: ln of the power then sits where the dataset's values do (about 10 to 27).
  std::vector<float> scaled(clip.mono.size());
  std::transform(clip.mono.begin(), clip.mono.end(), scaled.begin(),
                 [](float x) { return x * 32768.0f; });
  audio::FeatureMatrix power;
  stft.power(scaled, power);
  const std::size_t frames = power.rows;
  const std::size_t kept = static_cast<std::size_t>(stft.config().fft_size / 4 + 1);
  const std::size_t t_len = frames / kGridTimeBins, f_len = kept / kGridFrequencyBins;
  if (t_len == 0)
    throw InputError(
        fmt::format("the clip gives {} spectrogram frames, fewer than the {} time bins "
                    "of the spectrogram grid",
                    frames, kGridTimeBins));
  std::vector<double> grid;
  grid.reserve(kGridTimeBins * kGridFrequencyBins);
  for (std::size_t t = 0; t < kGridTimeBins; ++t)
    for (std::size_t f = 0; f < kGridFrequencyBins; ++f) {
      double sum = 0.0;
      for (std::size_t i = t * t_len; i < (t + 1) * t_len; ++i)
        for (std::size_t k = f * f_len; k < (f + 1) * f_len; ++k)
          sum += std::max(std::log(static_cast<double>(power.at(i, k))), 0.0);
      grid.push_back(sum / static_cast<double>(t_len * f_len));
    }
  return grid;
}

std::vector<std::string> spectrogram_grid_names() {
  std::vector<std::string> names;
  for (int t = 1; t <= kGridTimeBins; ++t)
    for (int f = 1; f <= kGridFrequencyBins; ++f) names.push_back(fmt::format("t{}_f{}", t, f));
  return names;
}

}  // namespace echoplan::perception
