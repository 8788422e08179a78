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
// table that did not count its own decisions (fit_feature_model: the table of the other inner
// folds): a table counting them has learnt the very confusions a session repeated, and looks
// calibrated when it is not.
#pragma once

#include <span>
#include <vector>

namespace echoplan::perception {

using Table = std::vector<std::vector<double>>;  // [class][symbol], rows sum to 1

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
