#include "perception/feature_classifier.h"

#include <fmt/format.h>

#include <Eigen/Dense>
#include <limits>

#include "common/error.h"
#include "perception/summary_lda_classifier.h"

namespace echoplan::perception {
namespace {

// Rows as an n x D matrix; InputError for ragged rows.
Eigen::MatrixXd to_matrix(std::span<const std::vector<double>> rows) {
  const auto d = rows.empty() ? Eigen::Index{0} : static_cast<Eigen::Index>(rows[0].size());
  Eigen::MatrixXd x(static_cast<Eigen::Index>(rows.size()), d);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (static_cast<Eigen::Index>(rows[i].size()) != d)
      throw InputError(fmt::format("feature rows have {} values, got {}", d, rows[i].size()));
    x.row(static_cast<Eigen::Index>(i)) = Eigen::Map<const Eigen::RowVectorXd>(rows[i].data(), d);
  }
  return x;
}

// Per-feature mean and deviation of the training rows (a constant feature keeps deviation 1).
struct Standardiser {
  Eigen::RowVectorXd mean, scale;
  void fit(const Eigen::MatrixXd& x) {
    mean = x.colwise().mean();
    const auto n = static_cast<double>(std::max<Eigen::Index>(1, x.rows() - 1));
    scale = ((x.rowwise() - mean).colwise().squaredNorm() / n).cwiseSqrt();
    for (Eigen::Index j = 0; j < scale.size(); ++j)
      if (!(scale(j) > 1e-12)) scale(j) = 1.0;
  }
  Eigen::MatrixXd apply(const Eigen::MatrixXd& x) const {
    return (x.rowwise() - mean).array().rowwise() / scale.array();
  }
  Eigen::RowVectorXd apply(std::span<const double> row) const {
    if (static_cast<Eigen::Index>(row.size()) != mean.size())
      throw InputError(fmt::format("feature rows have {} values, got {}", mean.size(), row.size()));
    return (Eigen::Map<const Eigen::RowVectorXd>(row.data(), mean.size()) - mean)
        .cwiseQuotient(scale);
  }
};

std::vector<int> check_labels(std::span<const int> labels, std::size_t rows, int num_classes) {
  if (labels.size() != rows) throw InputError("one label per feature row is needed");
  std::vector<int> counts(static_cast<std::size_t>(num_classes), 0);
  for (int label : labels) ++counts.at(static_cast<std::size_t>(label));
  for (int c = 0; c < num_classes; ++c)
    if (counts[static_cast<std::size_t>(c)] == 0)
      throw InputError(fmt::format("class {} has no training rows", c));
  return counts;
}

class LdaFeatureClassifier final : public FeatureClassifier {
 public:
  std::string name() const override { return "lda"; }
  void fit(std::span<const std::vector<double>> rows, std::span<const int> labels,
           int num_classes) override {
    const std::vector<int> counts = check_labels(labels, rows.size(), num_classes);
    Eigen::MatrixXd x = to_matrix(rows);
    standardiser_.fit(x);
    x = standardiser_.apply(x);
    Eigen::MatrixXd means = Eigen::MatrixXd::Zero(num_classes, x.cols());
    for (Eigen::Index i = 0; i < x.rows(); ++i)
      means.row(labels[static_cast<std::size_t>(i)]) += x.row(i);
    for (int c = 0; c < num_classes; ++c) means.row(c) /= counts[static_cast<std::size_t>(c)];
    Eigen::MatrixXd residuals(x.rows(), x.cols());
    for (Eigen::Index i = 0; i < x.rows(); ++i)
      residuals.row(i) = x.row(i) - means.row(labels[static_cast<std::size_t>(i)]);
    const double dof = std::max<double>(1.0, static_cast<double>(x.rows() - num_classes));
    auto [weight, covariance] = SummaryLdaClassifier::ledoit_wolf(residuals, dof);
    // A floor on the diagonal keeps a degenerate set (every residual zero) invertible.
    covariance.diagonal().array() += 1e-9;
    const Eigen::LLT<Eigen::MatrixXd> llt(covariance);
    if (llt.info() != Eigen::Success)
      throw InputError("the shared covariance is not positive definite");
    whitening_ = llt.matrixL().solve(Eigen::MatrixXd::Identity(x.cols(), x.cols()));
    white_means_ = means * whitening_.transpose();
  }
  std::vector<double> log_scores(std::span<const double> row) const override {
    const Eigen::VectorXd white =
        whitening_.triangularView<Eigen::Lower>() * standardiser_.apply(row).transpose();
    std::vector<double> scores(static_cast<std::size_t>(white_means_.rows()));
    for (Eigen::Index c = 0; c < white_means_.rows(); ++c)
      scores[static_cast<std::size_t>(c)] =
          -0.5 * (white - white_means_.row(c).transpose()).squaredNorm();
    return scores;
  }
  std::unique_ptr<FeatureClassifier> clone_unfitted() const override {
    return std::make_unique<LdaFeatureClassifier>();
  }

 private:
  Standardiser standardiser_;
  Eigen::MatrixXd whitening_;    // D x D lower triangular: W^T W = covariance^-1
  Eigen::MatrixXd white_means_;  // C x D
};

class NearestNeighbourFeatureClassifier final : public FeatureClassifier {
 public:
  std::string name() const override { return "nearest-neighbour"; }
  void fit(std::span<const std::vector<double>> rows, std::span<const int> labels,
           int num_classes) override {
    check_labels(labels, rows.size(), num_classes);
    const Eigen::MatrixXd x = to_matrix(rows);
    standardiser_.fit(x);
    rows_ = standardiser_.apply(x);
    squared_norms_ = rows_.rowwise().squaredNorm();
    labels_.assign(labels.begin(), labels.end());
    num_classes_ = num_classes;
  }
  std::vector<double> log_scores(std::span<const double> row) const override {
    const Eigen::RowVectorXd z = standardiser_.apply(row);
    // |x - z|^2 = |x|^2 - 2 x.z + |z|^2, one matrix-vector product for all training rows.
    const Eigen::VectorXd squared =
        (squared_norms_ - 2.0 * rows_ * z.transpose()).array() + z.squaredNorm();
    std::vector<double> nearest(static_cast<std::size_t>(num_classes_),
                                std::numeric_limits<double>::infinity());
    for (std::size_t i = 0; i < labels_.size(); ++i) {
      double& best = nearest[static_cast<std::size_t>(labels_[i])];
      best = std::min(best, std::max(0.0, squared(static_cast<Eigen::Index>(i))));
    }
    for (double& d : nearest) d = -0.5 * d;
    return nearest;
  }
  std::unique_ptr<FeatureClassifier> clone_unfitted() const override {
    return std::make_unique<NearestNeighbourFeatureClassifier>();
  }

 private:
  Standardiser standardiser_;
  Eigen::MatrixXd rows_;  // standardised training rows
  Eigen::VectorXd squared_norms_;
  std::vector<int> labels_;
  int num_classes_ = 0;
};

}  // namespace

std::vector<std::string> feature_classifier_names() { return {"lda", "nearest-neighbour"}; }

std::unique_ptr<FeatureClassifier> make_feature_classifier(std::string_view name) {
  if (name == "lda") return std::make_unique<LdaFeatureClassifier>();
  if (name == "nearest-neighbour") return std::make_unique<NearestNeighbourFeatureClassifier>();
  throw InputError(fmt::format("unknown feature classifier '{}' (expected {})", name,
                               fmt::join(feature_classifier_names(), ", ")));
}

}  // namespace echoplan::perception
