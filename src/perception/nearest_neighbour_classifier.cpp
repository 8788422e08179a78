#include "perception/nearest_neighbour_classifier.h"

#include <fmt/format.h>

#include <limits>
#include <nlohmann/json.hpp>

#include "common/error.h"
#include "common/json_fields.h"
#include "perception/row_matrix.h"

namespace echoplan::perception {
namespace {

namespace jf = json_fields;

}  // namespace

void NearestNeighbourClassifier::fit(std::span<const std::vector<double>> rows,
                                     std::span<const int> labels, int num_classes) {
  const Eigen::MatrixXd x = rows_to_matrix(rows, labels.size());
  std::vector<int> counts(static_cast<std::size_t>(num_classes), 0);
  for (int label : labels) {
    if (label < 0 || label >= num_classes)
      throw InputError(fmt::format("label {} is not a class in [0, {})", label, num_classes));
    ++counts[static_cast<std::size_t>(label)];
  }
  for (int c = 0; c < num_classes; ++c)
    if (counts[static_cast<std::size_t>(c)] == 0)
      throw InputError(fmt::format("class {} has no training rows", c));
  mean_ = x.colwise().mean();
  const auto n = static_cast<double>(std::max<Eigen::Index>(1, x.rows() - 1));
  scale_ = ((x.rowwise() - mean_).colwise().squaredNorm() / n).cwiseSqrt();
  for (Eigen::Index j = 0; j < scale_.size(); ++j)
    if (!(scale_(j) > 1e-12)) scale_(j) = 1.0;
  rows_ = (x.rowwise() - mean_).array().rowwise() / scale_.array();
  squared_norms_ = rows_.rowwise().squaredNorm();
  labels_.assign(labels.begin(), labels.end());
  num_classes_ = num_classes;
}

ClassScores NearestNeighbourClassifier::score(std::span<const double> row) const {
  if (static_cast<Eigen::Index>(row.size()) != mean_.size())
    throw InputError(fmt::format("feature rows have {} values, got {}", mean_.size(), row.size()));
  const Eigen::RowVectorXd z =
      (Eigen::Map<const Eigen::RowVectorXd>(row.data(), mean_.size()) - mean_)
          .cwiseQuotient(scale_);
  // |x - z|^2 = |x|^2 - 2 x.z + |z|^2, one matrix-vector product for all training rows.
  const Eigen::VectorXd squared =
      (squared_norms_ - 2.0 * rows_ * z.transpose()).array() + z.squaredNorm();
  std::vector<double> nearest(static_cast<std::size_t>(num_classes_),
                              std::numeric_limits<double>::infinity());
  for (std::size_t i = 0; i < labels_.size(); ++i) {
    double& best = nearest[static_cast<std::size_t>(labels_[i])];
    best = std::min(best, std::max(0.0, squared(static_cast<Eigen::Index>(i))));
  }
  ClassScores s;
  for (double d : nearest) {
    s.distances.push_back(std::sqrt(d));
    s.log_scores.push_back(-0.5 * d);
  }
  return s;
}

nlohmann::json NearestNeighbourClassifier::save() const {
  std::vector<double> flat(static_cast<std::size_t>(rows_.size()));
  Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
      flat.data(), rows_.rows(), rows_.cols()) = rows_;
  return {{"classes", num_classes_},
          {"mean", std::vector<double>(mean_.data(), mean_.data() + mean_.size())},
          {"scale", std::vector<double>(scale_.data(), scale_.data() + scale_.size())},
          {"labels", labels_},
          {"rows", jf::rows_of(flat, static_cast<std::size_t>(rows_.rows()),
                               static_cast<std::size_t>(rows_.cols()))}};
}

void NearestNeighbourClassifier::load(const nlohmann::json& fit, const std::string& source) {
  const std::string where = "classifier";
  const int classes = jf::integer(jf::member(fit, "classes", where, source), 1, 1 << 20,
                                  where + ".classes", source);
  const auto mean =
      jf::numbers(jf::member(fit, "mean", where, source), -1, where + ".mean", source);
  const auto d = static_cast<long long>(mean.size());
  if (d == 0) throw InputError(source, 0, where + ".mean: expected at least one feature");
  const auto scale =
      jf::numbers(jf::member(fit, "scale", where, source), d, where + ".scale", source);
  for (double v : scale)
    if (!(v > 0.0)) throw InputError(source, 0, where + ".scale: every entry must be positive");
  const auto labels =
      jf::integers(jf::member(fit, "labels", where, source), -1, where + ".labels", source);
  const auto rows = jf::matrix(jf::member(fit, "rows", where, source),
                               static_cast<long long>(labels.size()), d, where + ".rows", source);
  std::vector<bool> seen(static_cast<std::size_t>(classes), false);
  for (int label : labels) {
    if (label < 0 || label >= classes)
      throw InputError(
          source, 0, fmt::format("{}.labels: {} is not a class in [0, {})", where, label, classes));
    seen[static_cast<std::size_t>(label)] = true;
  }
  for (int c = 0; c < classes; ++c)
    if (!seen[static_cast<std::size_t>(c)])
      throw InputError(source, 0, fmt::format("{}.labels: class {} has no row", where, c));
  mean_ = Eigen::Map<const Eigen::RowVectorXd>(mean.data(), d);
  scale_ = Eigen::Map<const Eigen::RowVectorXd>(scale.data(), d);
  rows_ = Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
      rows.data(), static_cast<Eigen::Index>(labels.size()), d);
  squared_norms_ = rows_.rowwise().squaredNorm();
  labels_ = labels;
  num_classes_ = classes;
}

}  // namespace echoplan::perception
