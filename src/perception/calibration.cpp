#include "perception/calibration.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include "common/golden_section.h"

namespace echoplan::perception {

ConfusionMatrix ConfusionMatrix::zeros(std::vector<std::string> objects,
                                       std::vector<std::string> symbols) {
  ConfusionMatrix m;
  m.counts.assign(objects.size(), std::vector<int>(symbols.size(), 0));
  m.objects = std::move(objects);
  m.symbols = std::move(symbols);
  return m;
}

double ConfusionMatrix::accuracy() const {
  int right = 0, all = 0;
  for (std::size_t k = 0; k < objects.size(); ++k) {
    const auto it = std::find(symbols.begin(), symbols.end(), objects[k]);
    if (it == symbols.end()) continue;
    right += counts[k][static_cast<std::size_t>(it - symbols.begin())];
    all += std::accumulate(counts[k].begin(), counts[k].end(), 0);
  }
  return all == 0 ? 0.0 : static_cast<double>(right) / all;
}

int ConfusionMatrix::total() const {
  int sum = 0;
  for (const auto& row : counts) sum += std::accumulate(row.begin(), row.end(), 0);
  return sum;
}

std::vector<double> softmax(std::span<const double> log_scores, double temperature) {
  std::vector<double> p(log_scores.size());
  if (p.empty()) return p;
  const double top = *std::max_element(log_scores.begin(), log_scores.end());
  double sum = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i)
    sum += p[i] = std::exp((log_scores[i] - top) / temperature);
  for (double& v : p) v /= sum;
  return p;
}

namespace {

double cross_entropy(std::span<const std::vector<double>> log_scores, std::span<const int> labels,
                     double smoothing, double t) {
  double loss = 0.0;
  for (std::size_t i = 0; i < labels.size(); ++i) {
    const auto& s = log_scores[i];
    const double top = *std::max_element(s.begin(), s.end());
    double sum = 0.0, mean_scaled = 0.0;
    for (double v : s) {
      sum += std::exp((v - top) / t);
      mean_scaled += (v - top) / t;
    }
    mean_scaled /= static_cast<double>(s.size());
    const double log_sum = std::log(sum);
    // -log p_c = log_sum - scaled_c; the target's mass: 1 - smoothing on the label, smoothing
    // spread evenly.
    loss += (1.0 - smoothing) * (log_sum - (s[static_cast<std::size_t>(labels[i])] - top) / t) +
            smoothing * (log_sum - mean_scaled);
  }
  return loss;
}

}  // namespace

double fit_temperature(std::span<const std::vector<double>> log_scores, std::span<const int> labels,
                       double smoothing) {
  if (labels.empty()) return 1.0;
  if (!(smoothing >= 0.0 && smoothing < 1.0))
    throw std::invalid_argument("label smoothing must be in [0, 1)");
  // The cross-entropy of temperature scaling is convex in 1/T, hence unimodal in log T:
  // golden-section search.
  auto f = [&](double log_t) {
    return cross_entropy(log_scores, labels, smoothing, std::exp(log_t));
  };
  return std::exp(golden_section_minimum(f, std::log(1e-4), std::log(1e6)));
}

}  // namespace echoplan::perception
