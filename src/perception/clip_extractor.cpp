#include "perception/clip_extractor.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <array>

#include "common/error.h"
#include "perception/pcen_summary.h"
#include "perception/report_gaussian_classifier.h"
#include "perception/report_template_classifier.h"
#include "perception/spectrogram_grid.h"
#include "perception/summary_features.h"

namespace echoplan::perception {
namespace {

std::vector<double> summary_row(const ClipAnalysis& clip) {
  const auto s = summary_features(clip);
  return {s.begin(), s.end()};
}

std::vector<std::string> no_names() { return {}; }
std::vector<std::string> centroid_rms_names() { return {"centroid_hz", "rms"}; }

const std::array<ClipExtractor, 5>& extractors() {
  static const std::array<ClipExtractor, 5> all{
      ClipExtractor{"summary", summary_row, summary_feature_names},
      ClipExtractor{"onset-logfbank", ReportTemplateClassifier::onset_window, no_names},
      ClipExtractor{"centroid-rms", ReportGaussianClassifier::centroid_rms, centroid_rms_names},
      ClipExtractor{"spectrogram-grid", spectrogram_grid, spectrogram_grid_names},
      ClipExtractor{"pcen-summary", pcen_summary, pcen_summary_names}};
  return all;
}

}  // namespace

std::vector<std::string> clip_extractor_names() {
  std::vector<std::string> names;
  for (const ClipExtractor& e : extractors()) names.push_back(e.name);
  return names;
}

const ClipExtractor& clip_extractor(std::string_view name) {
  for (const ClipExtractor& e : extractors())
    if (e.name == name) return e;
  throw InputError(fmt::format("unknown clip extractor '{}' (expected {})", name,
                               fmt::join(clip_extractor_names(), ", ")));
}

}  // namespace echoplan::perception
