// The one table estimator: from one action's held-out decisions to P(symbol | class), the
// planner's observation table. Its options (TableOptions):
//   estimate  counts: one count per held-out example for the symbol it was reported as (a class,
//                     or `unknown` when the reject option rejected it), each row smoothed with a
//                     symmetric Dirichlet prior (alpha added to every cell: a row from few examples
//                     may hold zeros that would let one observation rule a class out for good);
//             soft:   each example adds its calibrated class probabilities instead of one count
//                     (soft_confusion; a rejected one its unit to `unknown`), then the same
//                     smoothing: narrow wins give softer rows;
//             shrunk: counts shrunk by empirical Bayes towards a pooled structure (below), for
//                     many classes from few examples each (a session-fitted model's table).
//   dirichlet_alpha  counts and soft: the pseudo-count per cell (1: Laplace's rule).
//   bin_of_class     shrunk: each class's bin, which the pooled structure distinguishes.
//   strength         shrunk: a given prior count; absent, the empirical-Bayes one is fitted.
// The reject option is a column: counts carry an `unknown` symbol when the model rejects.
// Tempering, for repeated performances of one action on one object (correlated, so the iid product
// overstates the evidence), is a second step on any table: temper() with fit_temper()'s beta.
//
// The calibrated observation table of a feature model (ObservationModel fitted on sessions), from
// held-out decisions.
//
// Shrinkage. With 100 classes and a few held-out rows per class, a count row (100 cells from ~4
// decisions) says almost nothing by itself. Each row is therefore shrunk towards a pooled
// structure shared by all classes of the action: P(right), P(wrong but same bin), P(other bin),
// estimated from all the action's decisions (plus one pseudo-count each, so none is 0), spread
// evenly over the row's same-bin and other-bin symbols (a class alone in its bin has no same-bin
// symbol: its prior row is renormalised). Row c is (counts_c + a * prior_c) / (n_c + a); the
// strength a is the empirical-Bayes estimate: it maximises the Dirichlet-multinomial marginal
// likelihood of all rows' counts (golden-section search on log a in [1e-2, 1e6]).
//
// Tempering. Repeated performances of one action on one object are correlated, so the iid product
// of table rows becomes overconfident over a session's sequence. Rows are replaced by p^beta
// renormalised, beta in [0.02, 1] minimising the NLL of the true class under the uniform-prior
// posterior after each held-out sequence (golden-section search). Each sequence is scored with a
// table that did not count its own decisions (fit_observation_model: the table of the other inner
// folds): a table counting them has learnt the very confusions a session repeated, and looks
// calibrated when it is not.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "perception/calibration.h"

namespace echoplan::perception {

using Table = std::vector<std::vector<double>>;  // [class][symbol], rows sum to 1

// How the cross-validated decisions become the observation table (before Dirichlet smoothing).
//   counts: each held-out clip adds one to (its object, the symbol it was reported as).
//   soft:   each held-out clip adds its calibrated probabilities softmax(log_scores / T) to its
//           object's row (a rejected clip still adds its whole unit to `unknown`): the expected
//           confusion under the calibrated classifier, so an action that wins by narrow margins
//           gets a softer row than one that wins by wide margins.
//   shrunk: a feature set's default: counts of fused decisions shrunk by empirical Bayes towards a
//           pooled structure, then tempered for repeats (below).
enum class TableEstimate { counts, soft, shrunk };
const char* table_estimate_name(TableEstimate estimate);
const std::vector<std::string>& table_estimate_names();
// Throws InputError("table estimate '<name>' is not one of: counts, soft, shrunk").
TableEstimate parse_table_estimate(const std::string& name);

struct TableOptions {
  TableEstimate estimate = TableEstimate::counts;
  double dirichlet_alpha = 1.0;    // counts, soft
  std::vector<int> bin_of_class;   // shrunk
  std::optional<double> strength;  // shrunk: given, or fitted when absent
};

struct EstimatedTable {
  Table table;
  double strength = 0.0;  // shrunk: the prior count used
};

// The table from counts[class][symbol] (hard counts, or soft_confusion's for `soft`); `classes`
// names the rows in errors. std::invalid_argument for a row with no counts and alpha 0, or a
// shrunk table whose symbols are not the classes.
EstimatedTable estimate_table(const std::vector<std::vector<double>>& counts,
                              const std::vector<std::string>& classes, const TableOptions& options);

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

struct ShrunkTable {
  Table table;
  double strength = 0.0;  // the empirical-Bayes prior count a
};

// The pooled prior row of every class, from counts[class][symbol] and each class's bin.
Table pooled_prior(const std::vector<std::vector<double>>& counts,
                   std::span<const int> bin_of_class);

// counts[class][symbol] (square: symbols are classes) shrunk as above.
ShrunkTable shrink_counts(const std::vector<std::vector<double>>& counts,
                          std::span<const int> bin_of_class);
// The same rows with a given strength (no search).
Table shrink_counts(const std::vector<std::vector<double>>& counts,
                    std::span<const int> bin_of_class, double strength);

// One held-out sequence: its true class and the symbols heard, in order.
struct Sequence {
  int true_class = 0;
  std::vector<int> symbols;
  int table = 0;  // which of the tables it is scored with (the multi-table functions)
  // Per symbol, which table scores it, for a sequence of several actions (each heard through its
  // own table); empty: every symbol is scored with `table`.
  std::vector<int> tables{};
};

// Rows p^beta, renormalised.
Table temper(const Table& table, double beta);

// Sum over sequences of -log P(true class | symbols) under temper(tables[sequence.table], beta),
// uniform prior.
double sequence_nll(std::span<const Table> tables, double beta,
                    std::span<const Sequence> sequences);
// The same with one table for all sequences.
double sequence_nll(const Table& table, double beta, std::span<const Sequence> sequences);

// The beta in [0.02, 1] minimising sequence_nll (1 when there are no sequences).
double fit_temper(std::span<const Table> tables, std::span<const Sequence> sequences);
double fit_temper(const Table& table, std::span<const Sequence> sequences);

}  // namespace echoplan::perception
