#include "perception/report_gaussian_classifier.h"

#include <fmt/format.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <numbers>

#include "audio/features.h"
#include "common/error.h"
#include "common/json_fields.h"

namespace echoplan::perception {

std::vector<double> ReportGaussianClassifier::centroid_rms(const ClipAnalysis& clip) {
  const auto g = audio::global_features(clip.mono, clip.sample_rate);
  return {g.centroid_hz, g.rms};
}

void ReportGaussianClassifier::fit(std::span<const std::vector<double>> examples,
                                   std::span<const int> labels, int num_classes) {
  const auto classes = static_cast<std::size_t>(num_classes);
  std::vector<std::array<double, 2>> sum(classes, {0.0, 0.0}), sum_sq(classes, {0.0, 0.0});
  std::vector<int> count(classes, 0);
  std::array<double, 2> all_sum{0.0, 0.0}, all_sq{0.0, 0.0};
  for (std::size_t i = 0; i < examples.size(); ++i) {
    const auto& x = examples[i];
    if (x.size() != 2) throw InputError("report-gaussian embeddings are (centroid, rms) pairs");
    const auto k = static_cast<std::size_t>(labels[i]);
    for (int d = 0; d < 2; ++d) {
      sum[k][d] += x[d];
      sum_sq[k][d] += x[d] * x[d];
      all_sum[d] += x[d];
      all_sq[d] += x[d] * x[d];
    }
    ++count[k];
  }
  const double n = static_cast<double>(examples.size());
  means_.assign(classes, {0.0, 0.0});
  variances_.assign(classes, {0.0, 0.0});
  for (std::size_t k = 0; k < classes; ++k) {
    if (count[k] == 0) throw InputError(fmt::format("class {} has no training recordings", k));
    for (int d = 0; d < 2; ++d) {
      const double pooled = std::max(all_sq[d] / n - (all_sum[d] / n) * (all_sum[d] / n), 0.0);
      // Floor: 5% of the pooled variance, and an absolute floor so that a set of identical clips
      // still works.
      const double floor = std::max(0.05 * pooled, 1e-12);
      means_[k][d] = sum[k][d] / count[k];
      variances_[k][d] = std::max(sum_sq[k][d] / count[k] - means_[k][d] * means_[k][d], floor);
    }
  }
}

ClassScores ReportGaussianClassifier::score(std::span<const double> x) const {
  if (x.size() != 2)
    throw InputError(
        fmt::format("report-gaussian scores (centroid, rms) pairs, got {} values", x.size()));
  ClassScores s;
  for (std::size_t k = 0; k < means_.size(); ++k) {
    double mahalanobis_sq = 0.0, log_det = 0.0;
    for (int d = 0; d < 2; ++d) {
      const double z = x[d] - means_[k][d];
      mahalanobis_sq += z * z / variances_[k][d];
      log_det += std::log(variances_[k][d]);
    }
    s.distances.push_back(std::sqrt(mahalanobis_sq));
    s.log_scores.push_back(-0.5 * (mahalanobis_sq + log_det) - std::log(2.0 * std::numbers::pi));
  }
  return s;
}

nlohmann::json ReportGaussianClassifier::save() const {
  nlohmann::json means = nlohmann::json::array(), variances = nlohmann::json::array();
  for (std::size_t k = 0; k < means_.size(); ++k) {
    means.push_back({means_[k][0], means_[k][1]});
    variances.push_back({variances_[k][0], variances_[k][1]});
  }
  return {{"features", {"centroid_hz", "rms"}}, {"means", means}, {"variances", variances}};
}

void ReportGaussianClassifier::load(const nlohmann::json& fit, const std::string& source) {
  const std::string where = "classifier";
  const auto means = json_fields::matrix(json_fields::member(fit, "means", where, source), -1, 2,
                                         where + ".means", source);
  const std::size_t classes = means.size() / 2;
  if (classes == 0) throw InputError(source, 0, where + ".means: expected at least one class");
  const auto variances =
      json_fields::matrix(json_fields::member(fit, "variances", where, source),
                          static_cast<long long>(classes), 2, where + ".variances", source);
  for (double v : variances)
    if (!(v > 0.0))
      throw InputError(source, 0, where + ".variances: every variance must be positive");
  means_.assign(classes, {});
  variances_.assign(classes, {});
  for (std::size_t k = 0; k < classes; ++k)
    for (std::size_t d = 0; d < 2; ++d) {
      means_[k][d] = means[k * 2 + d];
      variances_[k][d] = variances[k * 2 + d];
    }
}

}  // namespace echoplan::perception
