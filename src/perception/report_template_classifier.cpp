#include "perception/report_template_classifier.h"

#include <fmt/format.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "common/error.h"
#include "common/json_fields.h"

namespace echoplan::perception {

std::vector<double> ReportTemplateClassifier::onset_window(const ClipAnalysis& clip) {
  const audio::FeatureMatrix w =
      audio::onset_window(clip.features.log_mel, clip.onset_frame, kFramesBefore, kFramesAfter);
  return {w.values.begin(), w.values.end()};
}

double ReportTemplateClassifier::mean_absolute_difference(std::span<const double> a,
                                                          std::span<const double> b) {
  double sum = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) sum += std::abs(a[i] - b[i]);
  return a.empty() ? 0.0 : sum / static_cast<double>(a.size());
}

void ReportTemplateClassifier::fit(std::span<const std::vector<double>> examples,
                                   std::span<const int> labels, int num_classes) {
  const std::size_t length = examples.empty() ? 0 : examples.front().size();
  if (length == 0 || length % (kFramesBefore + kFramesAfter) != 0)
    throw InputError(fmt::format("template windows must hold {} frames of filterbank bands",
                                 kFramesBefore + kFramesAfter));
  std::vector<std::vector<double>> sums(static_cast<std::size_t>(num_classes),
                                        std::vector<double>(length, 0.0));
  std::vector<int> counts(static_cast<std::size_t>(num_classes), 0);
  for (std::size_t i = 0; i < examples.size(); ++i) {
    if (examples[i].size() != length) throw InputError("template windows of different sizes");
    auto& sum = sums[static_cast<std::size_t>(labels[i])];
    for (std::size_t j = 0; j < length; ++j) sum[j] += examples[i][j];
    ++counts[static_cast<std::size_t>(labels[i])];
  }
  for (std::size_t k = 0; k < sums.size(); ++k) {
    if (counts[k] == 0) throw InputError(fmt::format("class {} has no training recordings", k));
    for (double& v : sums[k]) v /= counts[k];
  }
  templates_ = std::move(sums);
  bands_ = length / (kFramesBefore + kFramesAfter);
}

ClassScores ReportTemplateClassifier::score(std::span<const double> embedding) const {
  ClassScores s;
  for (const auto& t : templates_) {
    if (t.size() != embedding.size())
      throw InputError(
          fmt::format("clip window has {} values, the templates {}", embedding.size(), t.size()));
    const double d = mean_absolute_difference(embedding, t);
    s.distances.push_back(d);
    s.log_scores.push_back(-d);
  }
  return s;
}

nlohmann::json ReportTemplateClassifier::save() const {
  nlohmann::json templates = nlohmann::json::array();
  for (const auto& t : templates_)
    templates.push_back(json_fields::rows_of(t, kFramesBefore + kFramesAfter, bands_));
  return {
      {"frames_before", kFramesBefore}, {"frames_after", kFramesAfter}, {"templates", templates}};
}

void ReportTemplateClassifier::load(const nlohmann::json& fit, const std::string& source) {
  const std::string where = "classifier";
  const auto rows = kFramesBefore + kFramesAfter;
  const int before = json_fields::integer(json_fields::member(fit, "frames_before", where, source),
                                          0, 1 << 20, where + ".frames_before", source);
  const int after = json_fields::integer(json_fields::member(fit, "frames_after", where, source), 0,
                                         1 << 20, where + ".frames_after", source);
  if (before != static_cast<int>(kFramesBefore) || after != static_cast<int>(kFramesAfter))
    throw InputError(source, 0,
                     fmt::format("{}: window must be {} frames before and {} after the onset",
                                 where, kFramesBefore, kFramesAfter));
  const auto& list = json_fields::member(fit, "templates", where, source);
  if (!list.is_array() || list.empty())
    throw InputError(source, 0, where + ".templates: expected a non-empty array");
  std::vector<std::vector<double>> templates;
  long long cols = -1;
  for (std::size_t k = 0; k < list.size(); ++k) {
    const std::string path = fmt::format("{}.templates[{}]", where, k);
    auto values = json_fields::matrix(list[k], static_cast<long long>(rows), cols, path, source);
    if (values.empty()) throw InputError(source, 0, path + ": empty template");
    cols = static_cast<long long>(values.size() / rows);
    templates.push_back(std::move(values));
  }
  templates_ = std::move(templates);
  bands_ = static_cast<std::size_t>(cols);
}

}  // namespace echoplan::perception
