#include "perception/shrunk_table.h"

#include <algorithm>
#include <cmath>
#include <functional>

#include "common/golden_section.h"

namespace echoplan::perception {
namespace {

enum Kind { right = 0, same_bin = 1, other_bin = 2 };

Kind kind(int true_class, int symbol, std::span<const int> bin_of_class) {
  if (symbol == true_class) return right;
  return bin_of_class[static_cast<std::size_t>(symbol)] ==
                 bin_of_class[static_cast<std::size_t>(true_class)]
             ? same_bin
             : other_bin;
}

// log of the Dirichlet-multinomial likelihood of every row's counts under Dirichlet(a * prior),
// without the multinomial coefficients (they do not depend on a).
double log_marginal(const std::vector<std::vector<double>>& counts, const Table& prior, double a) {
  double total = 0.0;
  for (std::size_t c = 0; c < counts.size(); ++c) {
    double n = 0.0;
    for (std::size_t o = 0; o < counts[c].size(); ++o) {
      if (counts[c][o] == 0.0) continue;  // lgamma(x) - lgamma(x) = 0
      const double alpha = a * prior[c][o];
      total += std::lgamma(counts[c][o] + alpha) - std::lgamma(alpha);
      n += counts[c][o];
    }
    total += std::lgamma(a) - std::lgamma(a + n);
  }
  return total;
}

}  // namespace

Table pooled_prior(const std::vector<std::vector<double>>& counts,
                   std::span<const int> bin_of_class) {
  const std::size_t classes = counts.size();
  double pooled[3] = {1.0, 1.0, 1.0};  // one pseudo-count each: no kind has probability 0
  for (std::size_t c = 0; c < classes; ++c)
    for (std::size_t o = 0; o < classes; ++o)
      pooled[kind(static_cast<int>(c), static_cast<int>(o), bin_of_class)] += counts[c][o];
  Table prior(classes, std::vector<double>(classes, 0.0));
  for (std::size_t c = 0; c < classes; ++c) {
    double members[3] = {0.0, 0.0, 0.0};
    for (std::size_t o = 0; o < classes; ++o)
      members[kind(static_cast<int>(c), static_cast<int>(o), bin_of_class)] += 1.0;
    double sum = 0.0;
    for (std::size_t o = 0; o < classes; ++o) {
      const Kind k = kind(static_cast<int>(c), static_cast<int>(o), bin_of_class);
      prior[c][o] = pooled[k] / members[k];
      sum += prior[c][o];
    }
    for (double& p : prior[c]) p /= sum;
  }
  return prior;
}

ShrunkTable shrink_counts(const std::vector<std::vector<double>>& counts,
                          std::span<const int> bin_of_class) {
  const Table prior = pooled_prior(counts, bin_of_class);
  const double log_a =
      golden_section_minimum([&](double x) { return -log_marginal(counts, prior, std::exp(x)); },
                             std::log(1e-2), std::log(1e6));
  return {shrink_counts(counts, bin_of_class, std::exp(log_a)), std::exp(log_a)};
}

Table shrink_counts(const std::vector<std::vector<double>>& counts,
                    std::span<const int> bin_of_class, double strength) {
  Table table = pooled_prior(counts, bin_of_class);
  for (std::size_t c = 0; c < counts.size(); ++c) {
    double n = 0.0;
    for (double count : counts[c]) n += count;
    for (std::size_t o = 0; o < counts[c].size(); ++o)
      table[c][o] = (counts[c][o] + strength * table[c][o]) / (n + strength);
  }
  return table;
}

Table temper(const Table& table, double beta) {
  Table tempered = table;
  for (auto& row : tempered) {
    double sum = 0.0;
    for (double& p : row) sum += (p = std::pow(p, beta));
    for (double& p : row) p /= sum;
  }
  return tempered;
}

double sequence_nll(std::span<const Table> tables, double beta,
                    std::span<const Sequence> sequences) {
  std::vector<Table> tempered;
  for (const Table& table : tables) tempered.push_back(temper(table, beta));
  double total = 0.0;
  std::vector<double> log_posterior(tables.front().size());
  for (const Sequence& sequence : sequences) {
    const Table& table = tempered.at(static_cast<std::size_t>(sequence.table));
    std::fill(log_posterior.begin(), log_posterior.end(), 0.0);
    for (int symbol : sequence.symbols)
      for (std::size_t c = 0; c < table.size(); ++c)
        log_posterior[c] += std::log(table[c][static_cast<std::size_t>(symbol)]);
    const double top = *std::max_element(log_posterior.begin(), log_posterior.end());
    double sum = 0.0;
    for (double l : log_posterior) sum += std::exp(l - top);
    total += top + std::log(sum) - log_posterior[static_cast<std::size_t>(sequence.true_class)];
  }
  return total;
}

double sequence_nll(const Table& table, double beta, std::span<const Sequence> sequences) {
  std::vector<Sequence> one_table(sequences.begin(), sequences.end());
  for (Sequence& s : one_table) s.table = 0;
  return sequence_nll(std::span<const Table>(&table, 1), beta, one_table);
}

double fit_temper(std::span<const Table> tables, std::span<const Sequence> sequences) {
  if (sequences.empty()) return 1.0;
  constexpr double kLowest = 0.02;
  const double beta = golden_section_minimum(
      [&](double b) { return sequence_nll(tables, b, sequences); }, kLowest, 1.0);
  // The search never evaluates the end points; keep 1 (no tempering) when it is at least as good.
  return sequence_nll(tables, 1.0, sequences) <= sequence_nll(tables, beta, sequences) ? 1.0 : beta;
}

double fit_temper(const Table& table, std::span<const Sequence> sequences) {
  std::vector<Sequence> one_table(sequences.begin(), sequences.end());
  for (Sequence& s : one_table) s.table = 0;
  return fit_temper(std::span<const Table>(&table, 1), one_table);
}

}  // namespace echoplan::perception
