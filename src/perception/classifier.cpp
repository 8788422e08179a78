#include "perception/classifier.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <array>
#include <nlohmann/json.hpp>

#include "common/error.h"

namespace echoplan::perception {
namespace {

struct Preset {
  const char* name;
  const char* extractor;
  const char* rows;
};

constexpr std::array<Preset, 6> kPresets{{{"summary-lda", "summary", "lda-class-scaled"},
                                          {"summary-nearest-mean", "summary", "nearest-mean"},
                                          {"report-template", "onset-logfbank", "template"},
                                          {"report-gaussian", "centroid-rms", "gaussian"},
                                          {"grid-lda", "spectrogram-grid", "lda-class-scaled"},
                                          {"pcen-lda", "pcen-summary", "lda-class-scaled"}}};

}  // namespace

Classifier::Classifier(std::string name, const ClipExtractor* extractor,
                       std::unique_ptr<RowClassifier> rows)
    : name_(std::move(name)), extractor_(extractor), rows_(std::move(rows)) {}

std::vector<double> Classifier::embed(const ClipAnalysis& clip) const {
  if (extractor_ == nullptr)
    throw InputError(fmt::format(
        "the '{}' classifier's rows are given by a sensor, not computed from a clip", name_));
  return extractor_->extract(clip);
}

std::unique_ptr<Classifier> Classifier::clone_unfitted() const {
  return std::make_unique<Classifier>(name_, extractor_, rows_->clone_unfitted());
}

nlohmann::json Classifier::save() const { return rows_->save(); }

void Classifier::load(const nlohmann::json& fit, const std::string& source) {
  rows_->load(fit, source);
}

std::vector<std::string> classifier_names() {
  std::vector<std::string> names;
  for (const Preset& p : kPresets) names.emplace_back(p.name);
  return names;
}

const std::map<std::string, std::string>& classifier_aliases() {
  static const std::map<std::string, std::string> aliases{{"seed-gaussian", "report-gaussian"},
                                                          {"seed-template", "report-template"}};
  return aliases;
}

bool is_audio_preset(std::string_view name) {
  const auto names = classifier_names();
  return std::find(names.begin(), names.end(), name) != names.end() ||
         classifier_aliases().count(std::string(name)) > 0;
}

std::unique_ptr<Classifier> make_classifier(std::string_view name) {
  if (const auto alias = classifier_aliases().find(std::string(name));
      alias != classifier_aliases().end())
    name = alias->second;
  for (const Preset& p : kPresets)
    if (name == p.name)
      return std::make_unique<Classifier>(p.name, &clip_extractor(p.extractor),
                                          make_row_classifier(p.rows));
  throw InputError(fmt::format("unknown classifier '{}' (expected {})", name,
                               fmt::join(classifier_names(), ", ")));
}

std::unique_ptr<Classifier> make_modality_classifier(std::string_view row_classifier,
                                                     std::string_view extractor) {
  auto rows = make_row_classifier(row_classifier);
  std::string name = rows->name();
  return std::make_unique<Classifier>(
      std::move(name), extractor.empty() ? nullptr : &clip_extractor(extractor), std::move(rows));
}

std::unique_ptr<Classifier> make_series_classifier(std::string_view name) {
  if (const auto alias = classifier_aliases().find(std::string(name));
      alias != classifier_aliases().end())
    name = alias->second;
  for (const Preset& p : kPresets)
    if (name == p.name) return make_modality_classifier(p.rows);
  return make_modality_classifier(name);
}

}  // namespace echoplan::perception
