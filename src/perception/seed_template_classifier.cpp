#include "perception/seed_template_classifier.h"

#include <fmt/format.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "common/error.h"
#include "perception/json_fields.h"

namespace echoplan::perception {

audio::FeatureMatrix SeedTemplateClassifier::window(const ClipAnalysis& clip) {
  return audio::onset_window(clip.features.log_mel, clip.onset_frame, kFramesBefore, kFramesAfter);
}

double SeedTemplateClassifier::mean_absolute_difference(const audio::FeatureMatrix& a,
                                                        const audio::FeatureMatrix& b) {
  double sum = 0.0;
  for (std::size_t i = 0; i < a.values.size(); ++i)
    sum += std::abs(static_cast<double>(a.values[i]) - b.values[i]);
  return a.values.empty() ? 0.0 : sum / static_cast<double>(a.values.size());
}

void SeedTemplateClassifier::fit(std::span<const ClipAnalysis* const> examples,
                                 std::span<const int> labels, int num_classes) {
  std::vector<std::vector<double>> sums(static_cast<std::size_t>(num_classes));
  std::vector<int> counts(static_cast<std::size_t>(num_classes), 0);
  std::size_t cols = 0;
  for (std::size_t i = 0; i < examples.size(); ++i) {
    const audio::FeatureMatrix w = window(*examples[i]);
    cols = w.cols;
    auto& sum = sums[static_cast<std::size_t>(labels[i])];
    sum.resize(w.values.size(), 0.0);
    for (std::size_t j = 0; j < w.values.size(); ++j) sum[j] += w.values[j];
    ++counts[static_cast<std::size_t>(labels[i])];
  }
  templates_.clear();
  for (int k = 0; k < num_classes; ++k) {
    if (counts[static_cast<std::size_t>(k)] == 0)
      throw InputError(fmt::format("class {} has no training recordings", k));
    audio::FeatureMatrix t;
    t.resize(kFramesBefore + kFramesAfter, cols);
    const auto& sum = sums[static_cast<std::size_t>(k)];
    for (std::size_t j = 0; j < t.values.size(); ++j)
      t.values[j] = static_cast<float>(sum[j] / counts[static_cast<std::size_t>(k)]);
    templates_.push_back(std::move(t));
  }
}

ClassScores SeedTemplateClassifier::score(const ClipAnalysis& clip) const {
  const audio::FeatureMatrix w = window(clip);
  ClassScores s;
  for (const auto& t : templates_) {
    if (t.cols != w.cols)
      throw InputError(
          fmt::format("clip has {} filterbank bands, the templates {}", w.cols, t.cols));
    const double d = mean_absolute_difference(w, t);
    s.distances.push_back(d);
    s.log_scores.push_back(-d);
  }
  return s;
}

nlohmann::json SeedTemplateClassifier::save() const {
  nlohmann::json templates = nlohmann::json::array();
  for (const auto& t : templates_)
    templates.push_back(json_fields::rows_of(std::vector<double>(t.values.begin(), t.values.end()),
                                             t.rows, t.cols));
  return {
      {"frames_before", kFramesBefore}, {"frames_after", kFramesAfter}, {"templates", templates}};
}

void SeedTemplateClassifier::load(const nlohmann::json& fit, const std::string& source) {
  const std::string where = "classifier";
  const auto rows = kFramesBefore + kFramesAfter;
  if (json_fields::integer(json_fields::member(fit, "frames_before", where, source), 0, 1 << 20,
                           where + ".frames_before", source) != static_cast<int>(kFramesBefore) ||
      json_fields::integer(json_fields::member(fit, "frames_after", where, source), 0, 1 << 20,
                           where + ".frames_after", source) != static_cast<int>(kFramesAfter))
    throw InputError(source, 0,
                     fmt::format("{}: window must be {} frames before and {} after the onset",
                                 where, kFramesBefore, kFramesAfter));
  const auto& list = json_fields::member(fit, "templates", where, source);
  if (!list.is_array() || list.empty())
    throw InputError(source, 0, where + ".templates: expected a non-empty array");
  std::vector<audio::FeatureMatrix> templates;
  long long cols = -1;
  for (std::size_t k = 0; k < list.size(); ++k) {
    const std::string path = fmt::format("{}.templates[{}]", where, k);
    const auto values =
        json_fields::matrix(list[k], static_cast<long long>(rows), cols, path, source);
    if (values.empty()) throw InputError(source, 0, path + ": empty template");
    cols = static_cast<long long>(values.size() / rows);
    audio::FeatureMatrix t;
    t.resize(rows, static_cast<std::size_t>(cols));
    for (std::size_t j = 0; j < values.size(); ++j) t.values[j] = static_cast<float>(values[j]);
    templates.push_back(std::move(t));
  }
  templates_ = std::move(templates);
}

}  // namespace echoplan::perception
