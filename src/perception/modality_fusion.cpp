#include "perception/modality_fusion.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "perception/calibration.h"

namespace echoplan::perception {
namespace {

// The NLL's gradient and Hessian in the weights: for one example with fused probabilities p,
// d/dw_m = E_p[s_m] - s_m(y) and d2/dw_m dw_n = Cov_p(s_m, s_n); summed over examples.
struct Derivatives {
  Eigen::VectorXd gradient;
  Eigen::MatrixXd hessian;
};

Derivatives derivatives(const ModalityScores& scores, std::span<const int> labels,
                        const std::vector<double>& weights) {
  const auto m_count = static_cast<Eigen::Index>(scores.size());
  Derivatives d{Eigen::VectorXd::Zero(m_count), Eigen::MatrixXd::Zero(m_count, m_count)};
  for (std::size_t i = 0; i < labels.size(); ++i) {
    std::vector<std::vector<double>> per_modality(scores.size());
    for (std::size_t m = 0; m < scores.size(); ++m) per_modality[m] = scores[m][i];
    const std::vector<double> p = softmax(fuse(per_modality, weights), 1.0);
    Eigen::VectorXd mean = Eigen::VectorXd::Zero(m_count);
    Eigen::MatrixXd second = Eigen::MatrixXd::Zero(m_count, m_count);
    Eigen::VectorXd s(m_count);
    for (std::size_t c = 0; c < p.size(); ++c) {
      for (Eigen::Index m = 0; m < m_count; ++m)
        s(m) = per_modality[static_cast<std::size_t>(m)][c];
      mean += p[c] * s;
      second += p[c] * s * s.transpose();
    }
    for (Eigen::Index m = 0; m < m_count; ++m)
      d.gradient(m) +=
          mean(m) - per_modality[static_cast<std::size_t>(m)][static_cast<std::size_t>(labels[i])];
    d.hessian += second - mean * mean.transpose();
  }
  const auto n = static_cast<double>(labels.size());
  d.gradient /= n;
  d.hessian /= n;
  return d;
}

// One projected Newton step from `w` (value `nll`) that lowers the NLL, or `w` itself.
std::vector<double> newton_step(const ModalityScores& scores, std::span<const int> labels,
                                const std::vector<double>& w, double nll) {
  const Derivatives d = derivatives(scores, labels, w);
  // Free weights: positive ones, and zeros the gradient would raise.
  std::vector<Eigen::Index> free;
  for (std::size_t m = 0; m < w.size(); ++m)
    if (w[m] > 0.0 || d.gradient(static_cast<Eigen::Index>(m)) < 0.0)
      free.push_back(static_cast<Eigen::Index>(m));
  if (free.empty()) return w;
  const auto k = static_cast<Eigen::Index>(free.size());
  Eigen::MatrixXd h(k, k);
  Eigen::VectorXd g(k);
  for (Eigen::Index a = 0; a < k; ++a) {
    g(a) = d.gradient(free[a]);
    for (Eigen::Index b = 0; b < k; ++b) h(a, b) = d.hessian(free[a], free[b]);
  }
  h.diagonal().array() += 1e-9 * (1.0 + h.diagonal().cwiseAbs().maxCoeff());
  const Eigen::VectorXd step = -h.ldlt().solve(g);
  for (double t = 1.0; t > 1e-6; t /= 2.0) {
    std::vector<double> next = w;
    for (Eigen::Index a = 0; a < k; ++a)
      next[static_cast<std::size_t>(free[a])] =
          std::max(0.0, w[static_cast<std::size_t>(free[a])] + t * step(a));
    if (fused_mean_nll(scores, labels, next) < nll) return next;
  }
  return w;
}

}  // namespace

std::vector<double> fuse(const std::vector<std::vector<double>>& scores,
                         const std::vector<double>& weights) {
  std::vector<double> fused(scores.front().size(), 0.0);
  for (std::size_t m = 0; m < scores.size(); ++m)
    if (weights[m] != 0.0)
      for (std::size_t c = 0; c < fused.size(); ++c) fused[c] += weights[m] * scores[m][c];
  return fused;
}

double fused_mean_nll(const ModalityScores& scores, std::span<const int> labels,
                      const std::vector<double>& weights) {
  double total = 0.0;
  std::vector<std::vector<double>> example(scores.size());
  for (std::size_t i = 0; i < labels.size(); ++i) {
    for (std::size_t m = 0; m < scores.size(); ++m) example[m] = scores[m][i];
    const std::vector<double> fused = fuse(example, weights);
    const double top = *std::max_element(fused.begin(), fused.end());
    double sum = 0.0;
    for (double z : fused) sum += std::exp(z - top);
    total += top + std::log(sum) - fused[static_cast<std::size_t>(labels[i])];
  }
  return total / static_cast<double>(labels.size());
}

Fusion fit_fusion(const ModalityScores& scores, std::span<const int> labels) {
  if (scores.empty() || labels.empty())
    throw std::invalid_argument("fusion needs at least one modality and one example");
  // Start: the best single modality at its own fitted temperature.
  Fusion best{std::vector<double>(scores.size(), 0.0), std::numeric_limits<double>::infinity()};
  for (std::size_t m = 0; m < scores.size(); ++m) {
    std::vector<double> w(scores.size(), 0.0);
    w[m] = 1.0 / fit_temperature(scores[m], labels);
    const double nll = fused_mean_nll(scores, labels, w);
    if (nll < best.mean_nll) best = {w, nll};
  }
  for (int iteration = 0; iteration < 50; ++iteration) {
    const std::vector<double> next = newton_step(scores, labels, best.weights, best.mean_nll);
    const double nll = fused_mean_nll(scores, labels, next);
    if (!(nll < best.mean_nll - 1e-12)) break;
    best = {next, nll};
  }
  return best;
}

}  // namespace echoplan::perception
