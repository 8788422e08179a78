#include "perception/lda_classifier.h"

#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include "common/error.h"
#include "common/json_fields.h"
#include "perception/ledoit_wolf.h"
#include "perception/row_matrix.h"

namespace echoplan::perception {
namespace {

namespace jf = json_fields;

constexpr double kClassScaleFloor = 0.05;  // class_scaled: the least within-class deviation
constexpr double kStandardRidge = 1e-9;    // standardise: added to the covariance's diagonal

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

// Sums the rows of `x` per class and divides by each class's count (InputError for an empty
// class).
Eigen::MatrixXd class_means(const Eigen::MatrixXd& x, std::span<const int> labels,
                            int num_classes) {
  Eigen::MatrixXd means = Eigen::MatrixXd::Zero(num_classes, x.cols());
  Eigen::VectorXd counts = Eigen::VectorXd::Zero(num_classes);
  for (Eigen::Index i = 0; i < x.rows(); ++i) {
    const int label = labels[static_cast<std::size_t>(i)];
    if (label < 0 || label >= num_classes)
      throw InputError(fmt::format("label {} is not a class in [0, {})", label, num_classes));
    means.row(label) += x.row(i);
    counts(label) += 1.0;
  }
  for (int k = 0; k < num_classes; ++k) {
    if (counts(k) == 0) throw InputError(fmt::format("class {} has no training rows", k));
    means.row(k) /= counts(k);
  }
  return means;
}

Eigen::MatrixXd residuals_of(const Eigen::MatrixXd& x, const Eigen::MatrixXd& means,
                             std::span<const int> labels) {
  Eigen::MatrixXd residuals(x.rows(), x.cols());
  for (Eigen::Index i = 0; i < x.rows(); ++i)
    residuals.row(i) = x.row(i) - means.row(labels[static_cast<std::size_t>(i)]);
  return residuals;
}

}  // namespace

std::string LdaClassifier::name() const {
  if (covariance_ == Covariance::identity) return "nearest-mean";
  return scaling_ == Scaling::standardise ? "lda" : "lda-class-scaled";
}

void LdaClassifier::fit_scaling(const Eigen::MatrixXd& x, std::span<const int> labels,
                                int num_classes, double dof, Eigen::MatrixXd& means,
                                Eigen::MatrixXd& residuals) {
  if (scaling_ == Scaling::standardise) {
    mean_ = x.colwise().mean().transpose();
    const auto n = static_cast<double>(std::max<Eigen::Index>(1, x.rows() - 1));
    scale_ = ((x.rowwise() - mean_.transpose()).colwise().squaredNorm() / n).cwiseSqrt();
    for (Eigen::Index j = 0; j < scale_.size(); ++j)
      if (!(scale_(j) > 1e-12)) scale_(j) = 1.0;
    const Eigen::MatrixXd z =
        (x.rowwise() - mean_.transpose()).array().rowwise() / scale_.transpose().array();
    means = class_means(z, labels, num_classes);
    residuals = residuals_of(z, means, labels);
    return;
  }
  // Class-scaled: the deviation is measured on the raw residuals, then everything is divided.
  const Eigen::MatrixXd raw_means = class_means(x, labels, num_classes);
  const Eigen::MatrixXd raw_residuals = residuals_of(x, raw_means, labels);
  mean_ = Eigen::VectorXd::Zero(x.cols());
  scale_ = (raw_residuals.colwise().squaredNorm().transpose() / dof)
               .cwiseSqrt()
               .cwiseMax(kClassScaleFloor);
  residuals = raw_residuals * scale_.cwiseInverse().asDiagonal();
  means = raw_means * scale_.cwiseInverse().asDiagonal();
}

void LdaClassifier::fit(std::span<const std::vector<double>> rows, std::span<const int> labels,
                        int num_classes) {
  const Eigen::MatrixXd x = rows_to_matrix(rows, labels.size());
  const auto d = x.cols();
  // Degrees of freedom of the pooled covariance: one mean per class is spent (at least 1 left).
  const double dof = std::max<double>(1.0, static_cast<double>(x.rows() - num_classes));
  Eigen::MatrixXd residuals;
  fit_scaling(x, labels, num_classes, dof, class_means_, residuals);
  Eigen::MatrixXd covariance;
  if (covariance_ == Covariance::ledoit_wolf) {
    ShrunkCovariance shrunk = ledoit_wolf(residuals, dof);
    shrinkage_ = shrunk.weight;
    covariance = std::move(shrunk.covariance);
    if (scaling_ == Scaling::standardise) covariance.diagonal().array() += kStandardRidge;
  } else {
    shrinkage_ = 1.0;
    covariance = Eigen::MatrixXd::Identity(d, d);
  }
  // Rows identical within every class (a deterministic sensor, copies of one recording) leave no
  // spread to estimate a metric from: then nothing tells one direction from another, and the
  // classes' means are compared in the scaled space as they are (the limit of any ridge).
  if (!(covariance.diagonal().maxCoeff() > 0.0)) {
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

Eigen::VectorXd LdaClassifier::scaled(std::span<const double> row) const {
  if (static_cast<Eigen::Index>(row.size()) != scale_.size())
    throw InputError(fmt::format("feature rows have {} values, got {}", scale_.size(), row.size()));
  return (Eigen::Map<const Eigen::VectorXd>(row.data(), scale_.size()) - mean_)
      .cwiseQuotient(scale_);
}

ClassScores LdaClassifier::score(std::span<const double> row) const {
  const Eigen::VectorXd white = whitening_.triangularView<Eigen::Lower>() * scaled(row);
  ClassScores s;
  for (Eigen::Index k = 0; k < white_means_.rows(); ++k) {
    const double sq = (white - white_means_.row(k).transpose()).squaredNorm();
    s.distances.push_back(std::sqrt(sq));
    s.log_scores.push_back(-0.5 * sq);
  }
  return s;
}

nlohmann::json LdaClassifier::save() const {
  const auto d = static_cast<std::size_t>(scale_.size());
  return {{"features", d},
          {"shrinkage", shrinkage_},
          {"mean", std::vector<double>(mean_.data(), mean_.data() + mean_.size())},
          {"scale", std::vector<double>(scale_.data(), scale_.data() + scale_.size())},
          {"class_means",
           jf::rows_of(to_vector(class_means_), static_cast<std::size_t>(class_means_.rows()), d)},
          {"whitening", jf::rows_of(to_vector(whitening_), d, d)}};
}

void LdaClassifier::load(const nlohmann::json& fit, const std::string& source) {
  const std::string where = "classifier";
  // Model format 1 wrote the summary-lda's length as summary_size.
  const char* length_key = fit.contains("summary_size") ? "summary_size" : "features";
  const auto d = static_cast<long long>(jf::integer(jf::member(fit, length_key, where, source), 1,
                                                    1 << 16, where + "." + length_key, source));
  const double shrinkage =
      jf::number(jf::member(fit, "shrinkage", where, source), where + ".shrinkage", source);
  if (shrinkage < 0.0 || shrinkage > 1.0)
    throw InputError(source, 0, where + ".shrinkage: must be in [0, 1]");
  const auto mean = fit.contains("mean") ? jf::numbers(fit["mean"], d, where + ".mean", source)
                                         : std::vector<double>(static_cast<std::size_t>(d), 0.0);
  const auto scale =
      jf::numbers(jf::member(fit, "scale", where, source), d, where + ".scale", source);
  for (double v : scale)
    if (!(v > 0.0)) throw InputError(source, 0, where + ".scale: every entry must be positive");
  const auto means = jf::matrix(jf::member(fit, "class_means", where, source), -1, d,
                                where + ".class_means", source);
  if (means.empty())
    throw InputError(source, 0, where + ".class_means: expected at least one class");
  const auto whitening =
      jf::matrix(jf::member(fit, "whitening", where, source), d, d, where + ".whitening", source);
  shrinkage_ = shrinkage;
  mean_ = Eigen::Map<const Eigen::VectorXd>(mean.data(), d);
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
