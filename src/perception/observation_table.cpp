#include "perception/observation_table.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numeric>
#include <stdexcept>

#include "common/error.h"
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
    std::fill(log_posterior.begin(), log_posterior.end(), 0.0);
    for (std::size_t i = 0; i < sequence.symbols.size(); ++i) {
      const int which = sequence.tables.empty() ? sequence.table : sequence.tables.at(i);
      const Table& table = tempered.at(static_cast<std::size_t>(which));
      for (std::size_t c = 0; c < table.size(); ++c)
        log_posterior[c] += std::log(table[c][static_cast<std::size_t>(sequence.symbols[i])]);
    }
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

const char* table_estimate_name(TableEstimate estimate) {
  switch (estimate) {
    case TableEstimate::soft:
      return "soft";
    case TableEstimate::shrunk:
      return "shrunk";
    case TableEstimate::counts:
      break;
  }
  return "counts";
}

const std::vector<std::string>& table_estimate_names() {
  static const std::vector<std::string> names{"counts", "soft", "shrunk"};
  return names;
}

TableEstimate parse_table_estimate(const std::string& name) {
  if (name == "counts") return TableEstimate::counts;
  if (name == "soft") return TableEstimate::soft;
  if (name == "shrunk") return TableEstimate::shrunk;
  throw InputError(fmt::format("table estimate '{}' is not one of: {}", name,
                               fmt::join(table_estimate_names(), ", ")));
}

std::vector<std::vector<double>> dirichlet_smoothed(const ConfusionMatrix& confusion,
                                                    double alpha) {
  std::vector<std::vector<double>> counts;
  for (const auto& row : confusion.counts) counts.emplace_back(row.begin(), row.end());
  return dirichlet_smoothed(counts, confusion.objects, alpha);
}

std::vector<std::vector<double>> dirichlet_smoothed(const std::vector<std::vector<double>>& counts,
                                                    const std::vector<std::string>& objects,
                                                    double alpha) {
  if (!(alpha >= 0.0)) throw std::invalid_argument("Dirichlet pseudo-count alpha must be >= 0");
  std::vector<std::vector<double>> table;
  for (std::size_t k = 0; k < counts.size(); ++k) {
    const auto& row = counts[k];
    const double n = std::accumulate(row.begin(), row.end(), 0.0);
    const double denominator = n + alpha * static_cast<double>(row.size());
    if (!(denominator > 0.0))
      throw std::invalid_argument("confusion row '" + (k < objects.size() ? objects[k] : "?") +
                                  "' has no counts and alpha is 0");
    std::vector<double> p(row.size());
    for (std::size_t o = 0; o < row.size(); ++o) p[o] = (row[o] + alpha) / denominator;
    table.push_back(std::move(p));
  }
  return table;
}

std::vector<std::vector<double>> soft_confusion(std::span<const std::vector<double>> log_scores,
                                                std::span<const int> labels,
                                                const std::vector<bool>& rejected, int num_classes,
                                                int num_symbols, double temperature) {
  if (num_classes < 1 || (num_symbols != num_classes && num_symbols != num_classes + 1))
    throw std::invalid_argument("soft_confusion: num_symbols must be num_classes or one more");
  if (log_scores.size() != labels.size() || (!rejected.empty() && rejected.size() != labels.size()))
    throw std::invalid_argument("soft_confusion: one label (and reject flag) per clip");
  const auto classes = static_cast<std::size_t>(num_classes);
  std::vector<std::vector<double>> counts(
      classes, std::vector<double>(static_cast<std::size_t>(num_symbols)));
  for (std::size_t i = 0; i < labels.size(); ++i) {
    if (labels[i] < 0 || labels[i] >= num_classes || log_scores[i].size() != classes)
      throw std::invalid_argument("soft_confusion: a label or a score row out of range");
    auto& row = counts[static_cast<std::size_t>(labels[i])];
    if (!rejected.empty() && rejected[i]) {
      if (num_symbols == num_classes)
        throw std::invalid_argument("soft_confusion: a rejected clip needs the unknown symbol");
      row[classes] += 1.0;
      continue;
    }
    const std::vector<double> p = softmax(log_scores[i], temperature);
    for (std::size_t c = 0; c < classes; ++c) row[c] += p[c];
  }
  return counts;
}

EstimatedTable estimate_table(const std::vector<std::vector<double>>& counts,
                              const std::vector<std::string>& classes,
                              const TableOptions& options) {
  if (options.estimate != TableEstimate::shrunk)
    return {dirichlet_smoothed(counts, classes, options.dirichlet_alpha), 0.0};
  for (const auto& row : counts)
    if (row.size() != counts.size())
      throw std::invalid_argument("a shrunk table's symbols are its classes");
  if (options.strength)
    return {shrink_counts(counts, options.bin_of_class, *options.strength), *options.strength};
  ShrunkTable shrunk = shrink_counts(counts, options.bin_of_class);
  return {std::move(shrunk.table), shrunk.strength};
}

}  // namespace echoplan::perception
