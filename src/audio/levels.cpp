#include "audio/levels.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace echoplan::audio {

namespace {

constexpr double kWindowS = 0.05;
constexpr double kBackgroundPercentile = 0.10;
constexpr double kLowestDb = -60.0, kHighestDb = 120.0;

// The mean square of each window of `seconds` every `hop_s` over the channels' average; one window
// of the whole clip when it is shorter.
std::vector<double> window_powers(const AudioClip& clip, double hop_s) {
  const std::size_t frames = clip.frames();
  std::vector<double> x(frames, 0.0);
  const auto channels = static_cast<std::size_t>(clip.channels);
  for (std::size_t f = 0; f < frames; ++f) {
    for (std::size_t c = 0; c < channels; ++c) x[f] += clip.samples[f * channels + c];
    x[f] /= static_cast<double>(channels);
  }
  std::vector<double> powers;
  if (x.empty()) return powers;
  const auto window = std::min<std::size_t>(
      x.size(), std::max<std::size_t>(1, static_cast<std::size_t>(kWindowS * clip.sample_rate)));
  const auto hop = std::max<std::size_t>(1, static_cast<std::size_t>(hop_s * clip.sample_rate));
  for (std::size_t begin = 0;; begin += hop) {
    const std::size_t from = std::min(begin, x.size() - window);
    double sum = 0.0;
    for (std::size_t i = from; i < from + window; ++i) sum += x[i] * x[i];
    powers.push_back(sum / static_cast<double>(window));
    if (from + window >= x.size()) break;
  }
  return powers;
}

}  // namespace

double event_level(const AudioClip& clip) {
  const std::vector<double> powers = window_powers(clip, 0.005);
  return powers.empty() ? 0.0 : std::sqrt(*std::max_element(powers.begin(), powers.end()));
}

double background_level(const AudioClip& clip) {
  std::vector<double> powers = window_powers(clip, 0.025);
  if (powers.empty()) return 0.0;
  const auto k =
      static_cast<std::size_t>(kBackgroundPercentile * static_cast<double>(powers.size()));
  std::nth_element(powers.begin(), powers.begin() + static_cast<std::ptrdiff_t>(k), powers.end());
  return std::sqrt(powers[k]);
}

double measured_ebr_db(const AudioClip& clip) {
  const double event = event_level(clip);
  if (event <= 0.0) return 0.0;
  const double background = background_level(clip);
  if (background <= 0.0) return kHighestDb;
  return std::clamp(20.0 * std::log10(event / background), kLowestDb, kHighestDb);
}

}  // namespace echoplan::audio
