// "template" (the row classifier of the `report-template` preset): the report's classifier
// (section 3.2.5), the baseline every other one is measured against.
//
// Per class, the template is the mean of the recordings' log filterbank matrices
// (python_speech_features logfbank: 26 filters, 25 ms frames, 10 ms step) over a fixed window of
// frames; a new clip is the class of the template with the smallest mean absolute difference. The
// one change from the report: the window is aligned on the clip's onset (10 frames before it, 140
// after: 1.5 s, the report's 150-frame strike window) instead of fixed frame offsets, which real
// recordings of varying length and silent starts defeat. Levels are compared as they are: a softer
// strike is further from its own template (what the original system did).
#pragma once

#include <vector>

#include "perception/clip_analysis.h"
#include "perception/row_classifier.h"

namespace echoplan::perception {

class ReportTemplateClassifier final : public RowClassifier {
 public:
  static constexpr std::size_t kFramesBefore = 10;
  static constexpr std::size_t kFramesAfter = 140;

  std::string name() const override { return "template"; }
  void fit(std::span<const std::vector<double>> examples, std::span<const int> labels,
           int num_classes) override;
  int num_classes() const override { return static_cast<int>(templates_.size()); }
  // log_scores = -distances; distances = mean |window - template| per class (natural-log units).
  ClassScores score(std::span<const double> embedding) const override;
  std::unique_ptr<RowClassifier> clone_unfitted() const override {
    return std::make_unique<ReportTemplateClassifier>();
  }
  nlohmann::json save() const override;
  void load(const nlohmann::json& fit, const std::string& source) override;

  // The onset-aligned logfbank window the templates compare (the "onset-logfbank" clip extractor),
  // row-major (kFramesBefore + kFramesAfter) x bands.
  static std::vector<double> onset_window(const ClipAnalysis& clip);

  // Mean absolute difference of two equally long vectors.
  static double mean_absolute_difference(std::span<const double> a, std::span<const double> b);

  const std::vector<std::vector<double>>& templates() const { return templates_; }

 private:
  std::vector<std::vector<double>> templates_;  // per class, window rows x bands, row-major
  std::size_t bands_ = 0;
};

}  // namespace echoplan::perception
