// Calibrating a classifier's scores: the confusion of its held-out decisions (object x reported
// symbol, what the table estimator of observation_table.h starts from), and temperature scaling,
// which turns log-scores into calibrated probabilities: one number T per action, chosen to
// minimise the cross-validated negative log-likelihood of the true classes.
#pragma once

#include <span>
#include <string>
#include <vector>

namespace echoplan::perception {

// Counts of (true object, reported symbol). Rows: objects; columns: observation symbols.
struct ConfusionMatrix {
  std::vector<std::string> objects;
  std::vector<std::string> symbols;
  std::vector<std::vector<int>> counts;  // objects.size() x symbols.size()

  // An all-zero matrix of the given labels.
  static ConfusionMatrix zeros(std::vector<std::string> objects, std::vector<std::string> symbols);
  // Fraction of recordings whose reported symbol is their own object (symbols named like the row's
  // object); rows for objects that are no symbol are left out. 0 for an empty matrix.
  double accuracy() const;
  int total() const;
};

// softmax(log_scores / temperature) (temperature > 0), computed stably.
std::vector<double> softmax(std::span<const double> log_scores, double temperature);

// The temperature in [1e-4, 1e6] minimising the cross-entropy sum_i sum_c target_ic * -log
// softmax(log_scores[i] / T)[c] (golden-section search on log T), where target_i puts 1 - smoothing
// on labels[i] and spreads `smoothing` evenly over all classes. With smoothing 0 a perfectly
// separated training set drives T to its lower bound (probabilities of exactly 0 and 1); a small
// smoothing (ObservationModel uses the Dirichlet prior's share of a row) keeps the probabilities as
// cautious as the smoothed table. Returns 1 when there are no examples.
double fit_temperature(std::span<const std::vector<double>> log_scores, std::span<const int> labels,
                       double smoothing = 0.0);

}  // namespace echoplan::perception
