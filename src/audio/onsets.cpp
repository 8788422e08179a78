#include "audio/onsets.h"

#include <fmt/format.h>

#include <algorithm>

#include "common/error.h"

namespace echoplan::audio {

std::vector<std::size_t> detect_onsets(const FeatureMatrix& flux, const OnsetConfig& config) {
  if (config.pre_max < 0 || config.post_max < 0 || config.pre_avg < 0 || config.post_avg < 0 ||
      config.wait < 0 || !(config.delta >= 0))
    throw InputError(
        "onset parameters pre_max, post_max, pre_avg, post_avg, wait and delta must be "
        "non-negative");
  const auto n = static_cast<std::ptrdiff_t>(flux.rows);
  std::vector<std::size_t> onsets;
  if (n == 0) return onsets;
  const float peak = *std::max_element(flux.values.begin(), flux.values.end());
  if (!(peak > 0.0f)) return onsets;
  auto value = [&](std::ptrdiff_t t) {
    return static_cast<double>(flux.values[static_cast<std::size_t>(t)]) / peak;
  };
  std::ptrdiff_t last = -(static_cast<std::ptrdiff_t>(config.wait) + 1);
  for (std::ptrdiff_t t = 0; t < n; ++t) {
    const double v = value(t);
    // Local maximum over the clipped window [t - pre_max, t + post_max].
    bool is_max = true;
    for (std::ptrdiff_t u = std::max<std::ptrdiff_t>(0, t - config.pre_max);
         u <= std::min(n - 1, t + config.post_max); ++u)
      if (value(u) > v) {
        is_max = false;
        break;
      }
    if (!is_max) continue;
    // Above the local mean by delta.
    double sum = 0.0;
    const std::ptrdiff_t lo = std::max<std::ptrdiff_t>(0, t - config.pre_avg);
    const std::ptrdiff_t hi = std::min(n - 1, t + config.post_avg);
    for (std::ptrdiff_t u = lo; u <= hi; ++u) sum += value(u);
    if (v < sum / static_cast<double>(hi - lo + 1) + config.delta) continue;
    if (t - last <= config.wait) continue;
    onsets.push_back(static_cast<std::size_t>(t));
    last = t;
  }
  return onsets;
}

std::size_t alignment_frame(const FeatureMatrix& flux, OnsetChoice choice,
                            const OnsetConfig& config) {
  if (flux.rows == 0) throw InputError("cannot align on an onset: the flux envelope has no frames");
  const auto onsets = detect_onsets(flux, config);
  if (onsets.empty())
    return static_cast<std::size_t>(std::max_element(flux.values.begin(), flux.values.end()) -
                                    flux.values.begin());
  if (choice == OnsetChoice::first) return onsets.front();
  return *std::max_element(onsets.begin(), onsets.end(), [&](std::size_t a, std::size_t b) {
    return flux.values[a] < flux.values[b];
  });
}

FeatureMatrix onset_window(const FeatureMatrix& features, std::size_t anchor, std::size_t before,
                           std::size_t after) {
  if (features.rows == 0)
    throw InputError("cannot cut an onset window from a matrix with no frames");
  FeatureMatrix out;
  out.resize(before + after, features.cols);
  const auto last = static_cast<std::ptrdiff_t>(features.rows) - 1;
  for (std::size_t r = 0; r < out.rows; ++r) {
    const std::ptrdiff_t source =
        std::clamp(static_cast<std::ptrdiff_t>(anchor + r) - static_cast<std::ptrdiff_t>(before),
                   std::ptrdiff_t{0}, last);
    std::copy_n(features.row(static_cast<std::size_t>(source)).begin(), features.cols,
                out.row(r).begin());
  }
  return out;
}

}  // namespace echoplan::audio
