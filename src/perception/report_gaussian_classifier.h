// "gaussian" (the row classifier of the `report-gaussian` preset): the report's first attempt, kept
// for the record: each class is a Gaussian over two whole-clip features, the spectral centroid (Hz)
// and the RMS level, with independent dimensions. The report discarded it; the benchmark shows why
// (docs/BENCHMARKS.md, "Perception").
//
// With 3-10 recordings a class's own variance is a poor estimate, so each class variance is floored
// at 5% of the variance pooled over all classes (never zero: identical recordings stay
// classifiable).
#pragma once

#include <array>
#include <vector>

#include "perception/clip_analysis.h"
#include "perception/row_classifier.h"

namespace echoplan::perception {

class ReportGaussianClassifier final : public RowClassifier {
 public:
  std::string name() const override { return "gaussian"; }
  // (centroid_hz, rms) of the whole clip (audio::global_features): the "centroid-rms" clip
  // extractor.
  static std::vector<double> centroid_rms(const ClipAnalysis& clip);
  void fit(std::span<const std::vector<double>> examples, std::span<const int> labels,
           int num_classes) override;
  int num_classes() const override { return static_cast<int>(means_.size()); }
  // log_scores: Gaussian log-densities; distances: Mahalanobis distances (diagonal covariance).
  ClassScores score(std::span<const double> embedding) const override;
  std::unique_ptr<RowClassifier> clone_unfitted() const override {
    return std::make_unique<ReportGaussianClassifier>();
  }
  nlohmann::json save() const override;
  void load(const nlohmann::json& fit, const std::string& source) override;

 private:
  std::vector<std::array<double, 2>> means_;
  std::vector<std::array<double, 2>> variances_;
};

}  // namespace echoplan::perception
