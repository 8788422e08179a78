// The LDA: every class a Gaussian with its own mean and one shared covariance, the pooled
// within-class covariance shrunk towards a multiple of the identity by the Ledoit-Wolf estimate
// (ledoit_wolf.h). Log-score = -Mahalanobis^2 / 2 to the class mean; distance = Mahalanobis.
//
// Features are first brought to a common scale, so that features in different units weigh alike,
// in one of two ways:
//   standardise   subtract the training rows' mean, divide by their standard deviation (a constant
//                 feature is divided by 1); a 1e-9 ridge on the covariance keeps a degenerate set
//                 (every residual zero) invertible. Registry name "lda", for feature sets.
//   class_scaled  divide by the pooled within-class standard deviation, floored at 0.05 so that a
//                 feature that never varies within a class cannot dominate. Registry name
//                 "lda-class-scaled": the `summary-lda` audio preset (123 summary features from
//                 12-40 recordings).
// With Covariance::identity the covariance step is skipped (shrinkage weight 1): Euclidean
// distance to each class mean of the scaled rows ("nearest-mean", the ablation that shows what the
// covariance adds).
#pragma once

#include <Eigen/Dense>

#include "perception/row_classifier.h"

namespace echoplan::perception {

class LdaClassifier final : public RowClassifier {
 public:
  enum class Scaling { standardise, class_scaled };
  enum class Covariance { ledoit_wolf, identity };
  LdaClassifier(Scaling scaling, Covariance covariance)
      : scaling_(scaling), covariance_(covariance) {}

  std::string name() const override;
  void fit(std::span<const std::vector<double>> rows, std::span<const int> labels,
           int num_classes) override;
  int num_classes() const override { return static_cast<int>(white_means_.rows()); }
  ClassScores score(std::span<const double> row) const override;
  std::unique_ptr<RowClassifier> clone_unfitted() const override {
    return std::make_unique<LdaClassifier>(scaling_, covariance_);
  }
  // {features, shrinkage, mean, scale, class_means, whitening}. Files written before `mean` and
  // `features` existed (the summary-lda of model format 1: `summary_size`, no mean) still load.
  nlohmann::json save() const override;
  void load(const nlohmann::json& fit, const std::string& source) override;

  // The shrinkage weight of the fit, in [0, 1] (1 with the identity covariance).
  double shrinkage() const { return shrinkage_; }

 private:
  // The scaled class means and residuals of a fit; sets mean_ and scale_.
  void fit_scaling(const Eigen::MatrixXd& x, std::span<const int> labels, int num_classes,
                   double dof, Eigen::MatrixXd& means, Eigen::MatrixXd& residuals);
  Eigen::VectorXd scaled(std::span<const double> row) const;

  Scaling scaling_;
  Covariance covariance_;
  double shrinkage_ = 1.0;
  Eigen::VectorXd mean_;         // D: subtracted first (zero when class-scaled)
  Eigen::VectorXd scale_;        // D: then divided by
  Eigen::MatrixXd class_means_;  // C x D: class means of the scaled rows
  Eigen::MatrixXd whitening_;    // D x D lower triangular: W^T W = shared covariance^-1
  Eigen::MatrixXd white_means_;  // C x D: W applied to each class mean
};

}  // namespace echoplan::perception
