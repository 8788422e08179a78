#include "perception/ledoit_wolf.h"

#include <algorithm>
#include <cmath>

namespace echoplan::perception {

ShrunkCovariance ledoit_wolf(const Eigen::MatrixXd& residuals, double dof) {
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

}  // namespace echoplan::perception
