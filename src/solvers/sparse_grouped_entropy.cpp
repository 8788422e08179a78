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
    : outcomes_(outcomes), groups_(groups), live_(live) {
  for (int k = 0; k < groups; ++k) {
    member_begin_.push_back(static_cast<int>(members_.size()));
    for (int l = 0; l < live; ++l)
      if (group_of_live[l] == k) members_.push_back(l);
  }
  member_begin_.push_back(static_cast<int>(members_.size()));
  slot_base_.push_back(0);
  for (int i = 0; i < sensing_actions; ++i)
    add_action(&emission_by_state[static_cast<std::size_t>(i) * live * outcomes]);
  constant_.resize(static_cast<std::size_t>(sensing_actions) * groups);
  slots_.resize(slot_base_.back());
  totals_.resize(outcomes);
  member_belief_.resize(members_.size());
}

void SparseGroupedEntropy::add_action(const double* rows) {
  const int O = outcomes_, K = groups_;
  const auto row_of = [&](int r) { return rows + static_cast<std::size_t>(members_[r]) * O; };
  // Each group's union of exceptional outcomes, in outcome order, and the slot of each.
  std::vector<std::map<int, int>> slot_of(K);
  const std::size_t base_begin = base_.size();
  for (int k = 0; k < K; ++k)
    for (int r = member_begin_[k]; r < member_begin_[k + 1]; ++r) {
      base_.push_back(most_frequent(row_of(r), O));
      for (int o = 0; o < O; ++o)
        if (row_of(r)[o] != base_.back()) slot_of[k].emplace(o, 0), ++exceptions_;
    }
  int slot = 0;
  for (int k = 0; k < K; ++k) {
    union_begin_.push_back(slot);
    for (auto& [o, s] : slot_of[k]) slot_outcome_.push_back(o), s = slot++;
  }
  union_begin_.push_back(slot);
  slot_base_.push_back(slot_base_.back() + slot);
  for (std::size_t r = 0; r < members_.size(); ++r)
    row_x_log_x_.push_back(sum_x_log_x(row_of(static_cast<int>(r)), O));
  for (int k = 0; k < K; ++k) {
    block_begin_.push_back(blocks_.size());
    for (int r = member_begin_[k]; r < member_begin_[k + 1]; ++r)
      for (const auto& [o, s] : slot_of[k]) blocks_.push_back(row_of(r)[o] - base_[base_begin + r]);
  }
}

double SparseGroupedEntropy::mean_exceptions() const {
  return base_.empty() ? 0.0 : static_cast<double>(exceptions_) / static_cast<double>(base_.size());
}

double SparseGroupedEntropy::expected_entropy(int i, const double* b) const {
  set_belief(b);
  return outcome_term(i) - group_term(i);
}

void SparseGroupedEntropy::set_belief(const double* b) const {
  for (std::size_t r = 0; r < members_.size(); ++r) member_belief_[r] = b[members_[r]];
  top_mass_ = -1.0;
  for (int k = 0; k < groups_; ++k) {
    double mass = 0.0;
    for (int r = member_begin_[k]; r < member_begin_[k + 1]; ++r) mass += member_belief_[r];
    if (mass > top_mass_) top_mass_ = mass, top_group_ = k;
  }
}

double SparseGroupedEntropy::top_group_slack(int i) const {
  const int k = top_group_;
  if (top_mass_ <= 0.0) return 0.0;
  const double* row = &row_x_log_x_[static_cast<std::size_t>(i) * live_];
  double bound = top_mass_ * std::log(top_mass_);
  for (int r = member_begin_[k]; r < member_begin_[k + 1]; ++r) bound += member_belief_[r] * row[r];
  return std::max(0.0, bound - one_group_term(i, k));
}

double SparseGroupedEntropy::one_group_term(int i, int k) const {
  const int* begin = &union_begin_[static_cast<std::size_t>(i) * (groups_ + 1)];
  const int width = begin[k + 1] - begin[k];
  return sum_x_log_x(slots_.data() + slot_base_[i] + begin[k], width) + off_union_term(i, k);
}

double SparseGroupedEntropy::off_union_term(int i, int k) const {
  const int* begin = &union_begin_[static_cast<std::size_t>(i) * (groups_ + 1)];
  const double c = constant_[static_cast<std::size_t>(i) * groups_ + k];
  return c > 0.0 ? static_cast<double>(outcomes_ - (begin[k + 1] - begin[k])) * c * std::log(c)
                 : 0.0;
}

double SparseGroupedEntropy::state_term(int i) const {
  return dot(member_belief_.data(), &row_x_log_x_[static_cast<std::size_t>(i) * live_],
             static_cast<std::size_t>(live_));
}

double SparseGroupedEntropy::outcome_term(int i) const {
  const int L = live_, O = outcomes_, K = groups_;
  const double* base = &base_[static_cast<std::size_t>(i) * L];
  const int* begin = &union_begin_[static_cast<std::size_t>(i) * (K + 1)];
  double* slots = slots_.data() + slot_base_[i];
  double* constant = &constant_[static_cast<std::size_t>(i) * K];
  // C[k] = Σ_{s in k} b(s) base(s) and their sum, the part every T[o] = Σ_k g[k][o] has.
  double all = 0.0;
  for (int k = 0; k < K; ++k) {
    double c = 0.0;
    for (int r = member_begin_[k]; r < member_begin_[k + 1]; ++r) c += member_belief_[r] * base[r];
    constant[k] = c;
    all += c;
  }
  // g[k][o] = C[k] + the group's deltas, each sum in state order; T[o] adds what they add, group
  // by group.
  std::fill(totals_.begin(), totals_.end(), all);
  const int* outcome_of = &slot_outcome_[slot_base_[i]];
  for (int k = 0; k < K; ++k)
    sum_scaled_rows(&slots[begin[k]], static_cast<std::size_t>(begin[k + 1] - begin[k]),
                    constant[k], &member_belief_[member_begin_[k]],
                    &blocks_[block_begin_[static_cast<std::size_t>(i) * K + k]],
                    static_cast<std::size_t>(member_begin_[k + 1] - member_begin_[k]),
                    totals_.data(), &outcome_of[begin[k]]);
  // A probability of 0 can come out a rounding error below it: sum_x_log_x counts it 0.
  return sum_x_log_x(totals_.data(), static_cast<std::size_t>(O));
}

double SparseGroupedEntropy::group_term(int i) const {
  const int K = groups_;
  const std::size_t width =
      static_cast<std::size_t>(union_begin_[static_cast<std::size_t>(i) * (K + 1) + K]);
  // Every group's union in one vectorised pass, then what each group is off it.
  double grouped = sum_x_log_x(slots_.data() + slot_base_[i], width);
  for (int k = 0; k < K; ++k) grouped += off_union_term(i, k);
  return grouped;
}

}  // namespace echoplan::solvers
