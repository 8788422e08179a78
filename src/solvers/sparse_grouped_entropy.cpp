#include "solvers/sparse_grouped_entropy.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "solvers/entropy_kernels.h"

namespace echoplan::solvers {

namespace {
// The value occurring most often in row[0..n) (the smallest of those on a tie).
double most_frequent(const double* row, int n) {
  std::vector<double> sorted(row, row + n);
  std::sort(sorted.begin(), sorted.end());
  double best = sorted[0];
  int best_count = 0;
  for (int i = 0, j = 0; i < n; i = j) {
    for (j = i; j < n && sorted[j] == sorted[i];) ++j;
    if (j - i > best_count) best = sorted[i], best_count = j - i;
  }
  return best;
}
}  // namespace

SparseGroupedEntropy::SparseGroupedEntropy(const std::vector<double>& emission_by_state,
                                           int sensing_actions, int live, int outcomes, int groups,
                                           const std::vector<int>& group_of_live)
    : outcomes_(outcomes), groups_(groups), live_(live), group_of_live_(group_of_live) {
  first_.push_back(0);
  for (int i = 0; i < sensing_actions; ++i)
    add_action(&emission_by_state[static_cast<std::size_t>(i) * live * outcomes]);
  constant_.resize(groups);
  totals_.resize(outcomes);
}

void SparseGroupedEntropy::add_action(const double* rows) {
  const int L = live_, O = outcomes_, K = groups_;
  // Each group's union of exceptional outcomes, in outcome order, and the slot of each.
  std::vector<std::map<int, int>> slot_of(K);
  const std::size_t state_begin = base_.size();
  slot_base_.push_back(slot_outcome_.size());
  for (int l = 0; l < L; ++l) {
    const double* row = rows + static_cast<std::size_t>(l) * O;
    base_.push_back(most_frequent(row, O));
    for (int o = 0; o < O; ++o)
      if (row[o] != base_.back()) slot_of[group_of_live_[l]].emplace(o, 0);
  }
  int slot = 0;
  for (int k = 0; k < K; ++k) {
    union_begin_.push_back(slot);
    for (auto& [o, s] : slot_of[k]) s = slot++;
  }
  union_begin_.push_back(slot);
  slots_.resize(std::max<std::size_t>(slots_.size(), slot));
  for (int k = 0; k < K; ++k)
    for (const auto& [o, s] : slot_of[k]) slot_outcome_.push_back(o), slot_group_.push_back(k);
  for (int l = 0; l < L; ++l) {
    const double* row = rows + static_cast<std::size_t>(l) * O;
    const double base = base_[state_begin + l];
    for (int o = 0; o < O; ++o)
      if (row[o] != base) exceptions_.push_back({slot_of[group_of_live_[l]].at(o), row[o] - base});
    first_.push_back(exceptions_.size());
  }
}

double SparseGroupedEntropy::mean_exceptions() const {
  return base_.empty()
             ? 0.0
             : static_cast<double>(exceptions_.size()) / static_cast<double>(base_.size());
}

double SparseGroupedEntropy::expected_entropy(int i, const double* b) const {
  const int L = live_, O = outcomes_, K = groups_;
  const double* base = &base_[static_cast<std::size_t>(i) * L];
  const std::size_t* first = &first_[static_cast<std::size_t>(i) * L];
  const int* begin = &union_begin_[static_cast<std::size_t>(i) * (K + 1)];
  std::fill(constant_.begin(), constant_.end(), 0.0);
  for (int l = 0; l < L; ++l) constant_[group_of_live_[l]] += b[l] * base[l];
  double all = 0.0;
  for (int k = 0; k < K; ++k) {
    std::fill(&slots_[begin[k]], &slots_[begin[k + 1]], constant_[k]);
    all += constant_[k];
  }
  for (int l = 0; l < L; ++l) {
    if (b[l] == 0.0) continue;
    for (std::size_t x = first[l]; x < first[l + 1]; ++x)
      slots_[exceptions_[x].slot] += b[l] * exceptions_[x].delta;
  }
  // T[o] = Σ_k g[k][o]: the constants' sum, and what each group's exceptions add at o.
  std::fill(totals_.begin(), totals_.end(), all);
  const std::size_t slot_base = slot_base_[i];
  for (int s = 0; s < begin[K]; ++s)
    totals_[slot_outcome_[slot_base + s]] += slots_[s] - constant_[slot_group_[slot_base + s]];
  // A probability of 0 can come out a rounding error below it: sum_x_log_x counts it 0.
  double grouped = sum_x_log_x(slots_.data(), static_cast<std::size_t>(begin[K]));
  for (int k = 0; k < K; ++k)
    if (const double c = constant_[k]; c > 0.0)
      grouped += static_cast<double>(O - (begin[k + 1] - begin[k])) * c * std::log(c);
  return sum_x_log_x(totals_.data(), static_cast<std::size_t>(O)) - grouped;
}

}  // namespace echoplan::solvers
