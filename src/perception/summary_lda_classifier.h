// `summary-lda` (the default) and `summary-nearest-mean`: few-shot classifiers on the
// level-normalised summary of a clip (perception/summary_features.h).
//
// Each summary entry is scaled by its pooled within-class standard deviation (floored at 0.05, so
// an entry that never varies in training cannot dominate). `summary-lda` then models every class as
// a Gaussian with the class mean and one shared covariance: the pooled within-class covariance
// shrunk towards a multiple of the identity by the Ledoit-Wolf estimate of the best shrinkage (123
// dimensions from 12-40 recordings need it). `summary-nearest-mean` skips the covariance (shrinkage
// 1): Euclidean distance to each class mean of the scaled summaries, the ablation that shows what
// the covariance adds. Distances are Mahalanobis distances to each class mean; log-scores are
// -distance^2 / 2.
#pragma once

#include <Eigen/Dense>

#include "perception/classifier.h"

namespace echoplan::perception {

class SummaryLdaClassifier final : public Classifier {
 public:
  enum class Covariance { ledoit_wolf, identity };
  explicit SummaryLdaClassifier(Covariance covariance = Covariance::ledoit_wolf)
      : covariance_(covariance) {}

  std::string name() const override {
    return covariance_ == Covariance::ledoit_wolf ? "summary-lda" : "summary-nearest-mean";
  }
  void fit(std::span<const ClipAnalysis* const> examples, std::span<const int> labels,
           int num_classes) override;
  int num_classes() const override { return static_cast<int>(class_means_.rows()); }
  ClassScores score(const ClipAnalysis& clip) const override;
  std::unique_ptr<Classifier> clone_unfitted() const override {
    return std::make_unique<SummaryLdaClassifier>(covariance_);
  }
  nlohmann::json save() const override;
  void load(const nlohmann::json& fit, const std::string& source) override;

  // The shrinkage weight of the fit, in [0, 1] (1 for nearest-mean).
  double shrinkage() const { return shrinkage_; }

  // Ledoit-Wolf (2004) shrinkage of the covariance of the rows of `residuals` (n x D, zero-mean per
  // class, divided by `dof`) towards mu I, mu = trace / D: returns (weight, covariance). Exposed
  // for tests.
  static std::pair<double, Eigen::MatrixXd> ledoit_wolf(const Eigen::MatrixXd& residuals,
                                                        double dof);

 private:
  Covariance covariance_;
  double shrinkage_ = 1.0;
  Eigen::VectorXd scale_;  // D: per-entry divisor (pooled within-class standard deviation, floored)
  Eigen::MatrixXd class_means_;  // C x D: class means of the scaled summaries
  Eigen::MatrixXd whitening_;    // D x D: W with W^T W = shared covariance^-1 (lower triangular)
  Eigen::MatrixXd white_means_;  // C x D: W applied to each class mean
};

}  // namespace echoplan::perception
