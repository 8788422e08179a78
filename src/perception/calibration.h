// From what a classifier really does to the planner's observation model P(o | object, action).
//
// Cross-validation gives, per action, a confusion matrix of counts (object x reported symbol). A
// row with few recordings estimates its probabilities poorly and may hold zeros that would let one
// observation rule an object out for good, so each row is smoothed with a symmetric Dirichlet prior
// (add alpha to every count). Temperature scaling turns classifier log-scores into calibrated
// probabilities: one number T per action, chosen to minimise the cross-validated negative
// log-likelihood of the true classes.
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

// P(symbol | object): (counts[k][o] + alpha) / (sum_o counts[k][o] + alpha * symbols). alpha >= 0;
// a row with no counts and alpha == 0 is an error (std::invalid_argument). alpha = 1 is Laplace's
// rule.
std::vector<std::vector<double>> dirichlet_smoothed(const ConfusionMatrix& confusion, double alpha);
// The same rule on real-valued counts (e.g. soft_confusion's); `objects` names the rows in errors.
std::vector<std::vector<double>> dirichlet_smoothed(const std::vector<std::vector<double>>& counts,
                                                    const std::vector<std::string>& objects,
                                                    double alpha);

// The expected confusion under the calibrated classifier ("soft counts"): row labels[i] receives
// softmax(log_scores[i] / temperature) over the first num_classes symbols instead of a one-hot
// count of the argmax; a clip with rejected[i] (farther than the reject threshold: reported
// `unknown` whatever its probabilities) puts its whole unit in symbol num_classes. Each clip adds 1
// to its row, so rows sum to what the hard counts' rows sum to. num_symbols is num_classes, or
// num_classes + 1 with the `unknown` symbol; `rejected` is empty or one flag per clip (a flag needs
// the unknown symbol). Throws std::invalid_argument for mismatched sizes or labels out of range.
std::vector<std::vector<double>> soft_confusion(std::span<const std::vector<double>> log_scores,
                                                std::span<const int> labels,
                                                const std::vector<bool>& rejected, int num_classes,
                                                int num_symbols, double temperature);

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
