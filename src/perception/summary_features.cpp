#include "perception/summary_features.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "common/error.h"

namespace echoplan::perception {
namespace {

constexpr std::size_t kCepstra = 12;  // c1..c12
constexpr std::size_t kWindow = 150;  // frames after the onset that the summary looks at
constexpr double kFloorNats = 12.0;   // log-mel floor below the peak frame level
constexpr std::array<double, 3> kDecayDb{10.0, 20.0, 30.0};

}  // namespace

std::array<double, kSummarySize> summary_features(const ClipAnalysis& clip) {
  const audio::FeatureMatrix& log_mel = clip.features.log_mel;
  const audio::FeatureMatrix& mfcc = clip.features.mfcc;
  if (log_mel.cols != kSummaryBands || mfcc.cols < kCepstra + 1)
    throw InputError(fmt::format(
        "summary features need 26 log-mel bands and 13 MFCCs (the psf preset), got {} and {}",
        log_mel.cols, mfcc.cols));
  if (log_mel.rows == 0) throw InputError("summary features need at least one frame");
  const std::size_t last = log_mel.rows - 1;
  const std::size_t onset = std::min(clip.onset_frame, last);
  // Frame `offset` after the onset; past the end of the clip, its last frame (the clip's tail
  // floor).
  auto frame = [&](std::size_t offset) { return std::min(onset + offset, last); };
  auto level = [&](std::size_t t) {
    double sum = 0.0;
    for (float v : log_mel.row(t)) sum += v;
    return sum / static_cast<double>(kSummaryBands);
  };

  std::array<double, kSummarySize> out{};
  const std::size_t end = std::min(onset + kWindow, log_mel.rows);
  std::size_t peak_frame = onset;
  double peak = level(onset);
  for (std::size_t t = onset; t < end; ++t)
    if (const double l = level(t); l > peak) {
      peak = l;
      peak_frame = t;
    }
  const double floor = peak - kFloorNats;

  std::size_t i = 0;
  for (const auto& [from, to] : kSummarySegments) {
    for (std::size_t b = 0; b < kSummaryBands; ++b) {
      double sum = 0.0;
      for (std::size_t f = from; f < to; ++f)
        sum += std::max(static_cast<double>(log_mel.at(frame(f), b)), floor);
      out[i++] = sum / static_cast<double>(to - from) - peak;
    }
  }

  for (std::size_t c = 1; c <= kCepstra; ++c) {
    double sum = 0.0, sum_sq = 0.0;
    for (std::size_t f = 0; f < kWindow; ++f) {
      const double v = mfcc.at(frame(f), c);
      sum += v;
      sum_sq += v * v;
    }
    const double mean = sum / kWindow;
    out[i++] = std::sqrt(std::max(sum_sq / kWindow - mean * mean, 0.0));
  }

  for (double db : kDecayDb) {
    const double threshold = peak - db * std::log(10.0) / 10.0;  // dB of power in nats
    std::size_t t = peak_frame;
    while (t < end && level(t) >= threshold) ++t;
    out[i++] = std::log1p(static_cast<double>(t - onset));
  }

  // Flatness of the floored mel spectrum (ln of geometric over arithmetic mean of the band
  // energies): unlike the STFT flatness, whose absolute power floor makes it depend on the level,
  // this is the same for a louder or softer copy.
  const std::array<std::pair<std::size_t, std::size_t>, 2> halves{{{0, 15}, {15, kWindow}}};
  for (const auto& [from, to] : halves) {
    double sum = 0.0;
    for (std::size_t f = from; f < to; ++f) {
      double log_mean = 0.0, mean = 0.0;
      for (float v : log_mel.row(frame(f))) {
        const double floored = std::max(static_cast<double>(v), floor) - peak;
        log_mean += floored;
        mean += std::exp(floored);
      }
      sum += log_mean / kSummaryBands - std::log(mean / kSummaryBands);
    }
    out[i++] = sum / static_cast<double>(to - from);
  }
  for (const auto& [from, to] : halves) {
    double sum = 0.0;
    for (std::size_t f = from; f < to; ++f) sum += clip.features.centroid.at(frame(f), 0);
    out[i++] = std::log(1.0 + sum / static_cast<double>(to - from));
  }
  return out;
}

std::vector<std::string> segment_band_names(std::string_view prefix) {
  std::vector<std::string> names;
  for (std::size_t s = 0; s < kSummarySegments.size(); ++s)
    for (std::size_t b = 0; b < kSummaryBands; ++b)
      names.push_back(fmt::format("{}{}_band{}", prefix, s, b));
  return names;
}

std::vector<std::string> summary_feature_names() {
  std::vector<std::string> names = segment_band_names("shape");
  for (std::size_t c = 1; c <= kCepstra; ++c) names.push_back(fmt::format("mfcc_std{}", c));
  for (double db : kDecayDb) names.push_back(fmt::format("decay{}", static_cast<int>(db)));
  names.insert(names.end(), {"flatness_early", "flatness_late", "centroid_early", "centroid_late"});
  return names;
}

}  // namespace echoplan::perception
