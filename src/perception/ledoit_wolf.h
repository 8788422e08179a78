// Ledoit-Wolf (2004) shrinkage of a sample covariance towards a multiple of the identity: the
// estimate every LDA in echoplan shares (50-120 features from a few dozen rows need it; the sample
// covariance alone is singular or nearly so).
#pragma once

#include <Eigen/Dense>

namespace echoplan::perception {

struct ShrunkCovariance {
  double weight = 1.0;         // the shrinkage weight in [0, 1] (1: the identity target alone)
  Eigen::MatrixXd covariance;  // (1 - weight) * sample + weight * mu I, mu = trace(sample) / D
};

// The covariance of the rows of `residuals` (n x D, zero-mean per class), divided by `dof` (the
// degrees of freedom left after the class means), shrunk by the Ledoit-Wolf estimate of the best
// weight. A residual matrix equal to its target (distance 0) gets weight 1.
ShrunkCovariance ledoit_wolf(const Eigen::MatrixXd& residuals, double dof);

}  // namespace echoplan::perception
