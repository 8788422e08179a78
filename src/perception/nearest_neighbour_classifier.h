// "nearest-neighbour": the nearest training row of each class, features standardised by the
// training rows' mean and deviation (a constant feature is divided by 1). 1-NN decides by the best
// class, as the datasets' reference results do. Log-score = -distance^2 / 2 to the class's nearest
// row; distance = that Euclidean distance. Suits classes made of several objects (a group held out
// by object), which are not one Gaussian. The fit keeps every training row.
#pragma once

#include <Eigen/Dense>

#include "perception/row_classifier.h"

namespace echoplan::perception {

class NearestNeighbourClassifier final : public RowClassifier {
 public:
  std::string name() const override { return "nearest-neighbour"; }
  void fit(std::span<const std::vector<double>> rows, std::span<const int> labels,
           int num_classes) override;
  int num_classes() const override { return num_classes_; }
  ClassScores score(std::span<const double> row) const override;
  std::unique_ptr<RowClassifier> clone_unfitted() const override {
    return std::make_unique<NearestNeighbourClassifier>();
  }
  // {mean, scale, labels, rows}: rows standardised.
  nlohmann::json save() const override;
  void load(const nlohmann::json& fit, const std::string& source) override;

 private:
  Eigen::RowVectorXd mean_, scale_;
  Eigen::MatrixXd rows_;  // standardised training rows
  Eigen::VectorXd squared_norms_;
  std::vector<int> labels_;
  int num_classes_ = 0;
};

}  // namespace echoplan::perception
