#include "perception/summary_lda_classifier.h"

#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include "common/error.h"
#include "common/json_fields.h"
#include "perception/summary_features.h"

namespace echoplan::perception {
namespace {

constexpr double kScaleFloor = 0.05;

std::vector<double> to_vector(const Eigen::MatrixXd& m) {
  std::vector<double> out(static_cast<std::size_t>(m.size()));
  Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
      out.data(), m.rows(), m.cols()) = m;
  return out;
}

Eigen::MatrixXd from_vector(const std::vector<double>& v, Eigen::Index rows, Eigen::Index cols) {
  return Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
      v.data(), rows, cols);
}

}  // namespace

std::pair<double, Eigen::MatrixXd> SummaryLdaClassifier::ledoit_wolf(
    const Eigen::MatrixXd& residuals, double dof) {
  const auto n = static_cast<double>(residuals.rows());
  const auto d = residuals.cols();
  const Eigen::MatrixXd sample = residuals.transpose() * residuals / dof;
  const double mu = sample.trace() / static_cast<double>(d);
  const Eigen::MatrixXd target = mu * Eigen::MatrixXd::Identity(d, d);
  const double distance = (sample - target).squaredNorm();
  // b^2: the average squared distance of each rank-one term from the sample covariance, over n^2.
  double spread = 0.0;
  const double sample_norm = sample.squaredNorm();
  for (Eigen::Index i = 0; i < residuals.rows(); ++i) {
    const Eigen::VectorXd z = residuals.row(i).transpose() * std::sqrt(n / dof);
    spread += z.squaredNorm() * z.squaredNorm() - 2.0 * z.dot(sample * z) + sample_norm;
  }
  spread /= n * n;
  const double weight = distance > 0.0 ? std::clamp(spread / distance, 0.0, 1.0) : 1.0;
  return {weight, (1.0 - weight) * sample + weight * target};
}

std::vector<double> SummaryLdaClassifier::embed(const ClipAnalysis& clip) const {
  const auto s = summary_features(clip);
  return {s.begin(), s.end()};
}

void SummaryLdaClassifier::fit(std::span<const std::vector<double>> examples,
                               std::span<const int> labels, int num_classes) {
  const auto n = static_cast<Eigen::Index>(examples.size());
  const auto d = static_cast<Eigen::Index>(kSummarySize);
  Eigen::MatrixXd x(n, d);
  for (Eigen::Index i = 0; i < n; ++i) {
    const auto& e = examples[static_cast<std::size_t>(i)];
    if (e.size() != kSummarySize)
      throw InputError(
          fmt::format("summary embeddings have {} values, got {}", kSummarySize, e.size()));
    x.row(i) = Eigen::Map<const Eigen::RowVectorXd>(e.data(), d);
  }
  Eigen::MatrixXd means = Eigen::MatrixXd::Zero(num_classes, d);
  Eigen::VectorXd counts = Eigen::VectorXd::Zero(num_classes);
  for (Eigen::Index i = 0; i < n; ++i) {
    means.row(labels[static_cast<std::size_t>(i)]) += x.row(i);
    counts(labels[static_cast<std::size_t>(i)]) += 1.0;
  }
  for (int k = 0; k < num_classes; ++k) {
    if (counts(k) == 0) throw InputError(fmt::format("class {} has no training recordings", k));
    means.row(k) /= counts(k);
  }
  Eigen::MatrixXd residuals(n, d);
  for (Eigen::Index i = 0; i < n; ++i)
    residuals.row(i) = x.row(i) - means.row(labels[static_cast<std::size_t>(i)]);
  // Degrees of freedom of the pooled covariance: one mean per class is spent (at least 1 left).
  const double dof = std::max<double>(1.0, static_cast<double>(n - num_classes));
  scale_ = (residuals.colwise().squaredNorm().transpose() / dof).cwiseSqrt().cwiseMax(kScaleFloor);
  const Eigen::MatrixXd scaled_residuals = residuals * scale_.cwiseInverse().asDiagonal();
  class_means_ = means * scale_.cwiseInverse().asDiagonal();

  Eigen::MatrixXd covariance;
  if (covariance_ == Covariance::ledoit_wolf) {
    std::tie(shrinkage_, covariance) = ledoit_wolf(scaled_residuals, dof);
  } else {
    shrinkage_ = 1.0;
    covariance = Eigen::MatrixXd::Identity(d, d);
  }
  // Sigma = L L^T, so Sigma^-1 = L^-T L^-1 and W = L^-1 whitens.
  const Eigen::LLT<Eigen::MatrixXd> llt(covariance);
  if (llt.info() != Eigen::Success)
    throw InputError("the shared covariance is not positive definite");
  whitening_ = llt.matrixL().solve(Eigen::MatrixXd::Identity(d, d));
  white_means_ = class_means_ * whitening_.transpose();
}

ClassScores SummaryLdaClassifier::score(std::span<const double> embedding) const {
  if (static_cast<Eigen::Index>(embedding.size()) != scale_.size())
    throw InputError(
        fmt::format("summary embeddings have {} values, got {}", scale_.size(), embedding.size()));
  const Eigen::VectorXd z =
      Eigen::Map<const Eigen::VectorXd>(embedding.data(), scale_.size()).cwiseQuotient(scale_);
  const Eigen::VectorXd white = whitening_.triangularView<Eigen::Lower>() * z;
  ClassScores s;
  for (Eigen::Index k = 0; k < white_means_.rows(); ++k) {
    const double sq = (white - white_means_.row(k).transpose()).squaredNorm();
    s.distances.push_back(std::sqrt(sq));
    s.log_scores.push_back(-0.5 * sq);
  }
  return s;
}

nlohmann::json SummaryLdaClassifier::save() const {
  const auto d = static_cast<std::size_t>(scale_.size());
  return {{"summary_size", d},
          {"shrinkage", shrinkage_},
          {"scale", std::vector<double>(scale_.data(), scale_.data() + scale_.size())},
          {"class_means", json_fields::rows_of(to_vector(class_means_),
                                               static_cast<std::size_t>(class_means_.rows()), d)},
          {"whitening", json_fields::rows_of(to_vector(whitening_), d, d)}};
}

void SummaryLdaClassifier::load(const nlohmann::json& fit, const std::string& source) {
  const std::string where = "classifier";
  const auto d = static_cast<long long>(kSummarySize);
  json_fields::integer(json_fields::member(fit, "summary_size", where, source), d, d,
                       where + ".summary_size", source);
  const double shrinkage = json_fields::number(json_fields::member(fit, "shrinkage", where, source),
                                               where + ".shrinkage", source);
  if (shrinkage < 0.0 || shrinkage > 1.0)
    throw InputError(source, 0, where + ".shrinkage: must be in [0, 1]");
  const auto scale = json_fields::numbers(json_fields::member(fit, "scale", where, source), d,
                                          where + ".scale", source);
  for (double v : scale)
    if (!(v > 0.0)) throw InputError(source, 0, where + ".scale: every entry must be positive");
  const auto means = json_fields::matrix(json_fields::member(fit, "class_means", where, source), -1,
                                         d, where + ".class_means", source);
  if (means.empty())
    throw InputError(source, 0, where + ".class_means: expected at least one class");
  const auto whitening = json_fields::matrix(json_fields::member(fit, "whitening", where, source),
                                             d, d, where + ".whitening", source);
  shrinkage_ = shrinkage;
  scale_ = Eigen::Map<const Eigen::VectorXd>(scale.data(), d);
  class_means_ = from_vector(means, static_cast<Eigen::Index>(means.size()) / d, d);
  whitening_ = from_vector(whitening, d, d);
  // Only the lower triangle is used: a whitening with anything above the diagonal was not written
  // by save().
  if (whitening_.triangularView<Eigen::StrictlyUpper>().toDenseMatrix().cwiseAbs().maxCoeff() !=
      0.0)
    throw InputError(source, 0, where + ".whitening: must be lower triangular");
  white_means_ = class_means_ * whitening_.transpose();
}

}  // namespace echoplan::perception
