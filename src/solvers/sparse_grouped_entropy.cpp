#include "solvers/sparse_grouped_entropy.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "solvers/entropy_kernels.h"

namespace echoplan::solvers {

namespace {
// The value occurring most often among row[outcomes[..]] (the smallest of those on a tie).
double most_frequent(const double* row, const std::vector<int>& outcomes) {
  std::vector<double> sorted;
  for (int o : outcomes) sorted.push_back(row[o]);
  std::sort(sorted.begin(), sorted.end());
  double best = sorted[0];
  int best_count = 0;
  for (std::size_t i = 0, j = 0; i < sorted.size(); i = j) {
    for (j = i; j < sorted.size() && sorted[j] == sorted[i];) ++j;
    if (static_cast<int>(j - i) > best_count)
      best = sorted[i], best_count = static_cast<int>(j - i);
  }
  return best;
}

// The outcomes split into classes whose cells agree in more than half of the `rows` (each
// `outcomes` long), the largest class 0. First each outcome joins the first class whose first
// outcome it so agrees with (of at most kCandidates: on a dense table no two outcomes agree, and
// the search stops costing outcomes squared; the outcomes left over make one more); classes of
// fewer than an eighth of the outcomes, and any beyond the `most` largest, fold into the largest.
// Then each outcome moves to the class whose most frequent value per row it equals in the most rows
// (a first outcome that was itself an exception in many rows splits its class less so); one that
// matches none in more than half the rows stays.
std::vector<int> outcome_classes(const double* rows, int count, int outcomes, int most) {
  const auto cell = [&](int r, int o) { return rows[static_cast<std::size_t>(r) * outcomes + o]; };
  constexpr std::size_t kCandidates = 32;
  std::vector<int> first, class_of(outcomes);
  for (int o = 0; o < outcomes; ++o) {
    std::size_t c = 0;
    for (; c < first.size() && c < kCandidates; ++c) {
      int equal = 0;
      for (int r = 0; r < count; ++r) equal += cell(r, o) == cell(r, first[c]);
      if (2 * equal > count) break;
    }
    if (c == first.size()) first.push_back(o);
    class_of[o] = static_cast<int>(c);
  }
  std::vector<int> size(first.size(), 0);
  for (int c : class_of) ++size[c];
  std::vector<int> order(first.size());
  for (std::size_t c = 0; c < order.size(); ++c) order[c] = static_cast<int>(c);
  std::stable_sort(order.begin(), order.end(), [&](int x, int y) { return size[x] > size[y]; });
  std::vector<int> renamed(first.size(), 0);  // kept classes by size, the rest into the largest
  int classes = 1;
  for (std::size_t n = 1; n < order.size(); ++n)
    if (static_cast<int>(n) < most && 8 * size[order[n]] >= outcomes) renamed[order[n]] = classes++;
  for (int& c : class_of) c = renamed[c];
  if (classes == 1) return class_of;
  std::vector<std::vector<int>> members(classes);
  for (int o = 0; o < outcomes; ++o) members[class_of[o]].push_back(o);
  std::vector<double> mode(static_cast<std::size_t>(count) * classes);
  for (int r = 0; r < count; ++r)
    for (int c = 0; c < classes; ++c)
      mode[static_cast<std::size_t>(r) * classes + c] =
          most_frequent(rows + static_cast<std::size_t>(r) * outcomes, members[c]);
  for (int o = 0; o < outcomes; ++o) {
    int best = count / 2;  // more than half the rows, or stay
    for (int c = 0; c < classes; ++c) {
      int equal = 0;
      for (int r = 0; r < count; ++r)
        equal += cell(r, o) == mode[static_cast<std::size_t>(r) * classes + c];
      if (equal > best) best = equal, class_of[o] = c;
    }
  }
  // A class all of whose outcomes moved is gone: number the others in order.
  std::vector<int> used(classes, 0), number(classes, 0);
  for (int c : class_of) used[c] = 1;
  for (int c = 1; c < classes; ++c) number[c] = number[c - 1] + used[c - 1];
  for (int& c : class_of) c = number[c];
  return class_of;
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
  constant_.resize(static_cast<std::size_t>(sensing_actions) * groups * kMaxClasses);
  slots_.resize(slot_base_.back());
  totals_.resize(outcomes);
  member_belief_.resize(members_.size());
}

void SparseGroupedEntropy::add_action(const double* rows) {
  const int O = outcomes_, K = groups_, i = static_cast<int>(classes_.size());
  const auto row_of = [&](int r) { return rows + static_cast<std::size_t>(members_[r]) * O; };
  const std::vector<int> class_of = outcome_classes(rows, live_, O, kMaxClasses);
  const int classes = *std::max_element(class_of.begin(), class_of.end()) + 1;
  classes_.push_back(classes);
  class_of_.insert(class_of_.end(), class_of.begin(), class_of.end());
  std::vector<std::vector<int>> class_outcomes(classes);
  for (int o = 0; o < O; ++o) class_outcomes[class_of[o]].push_back(o);
  // Each row's base value per class, and each group's union of exceptional outcomes by class.
  std::vector<std::vector<std::map<int, int>>> slot_of(K, std::vector<std::map<int, int>>(classes));
  const std::size_t base_begin = base_.size();
  base_.resize(base_begin + members_.size() * kMaxClasses, 0.0);
  const auto base = [&](int r, int c) -> double& {
    return base_[base_begin + r * kMaxClasses + c];
  };
  for (int k = 0; k < K; ++k)
    for (int r = member_begin_[k]; r < member_begin_[k + 1]; ++r)
      for (int c = 0; c < classes; ++c) {
        base(r, c) = most_frequent(row_of(r), class_outcomes[c]);
        for (int o : class_outcomes[c])
          if (row_of(r)[o] != base(r, c)) slot_of[k][c].emplace(o, 0), ++exceptions_;
      }
  int slot = 0;
  segment_begin_.resize(at(i + 1, 0, 0));
  off_union_.resize(at(i + 1, 0, 0));
  for (int k = 0; k < K; ++k) {
    union_begin_.push_back(slot);
    for (int c = 0; c < classes; ++c) {
      segment_begin_[at(i, k, c)] = slot;
      off_union_[at(i, k, c)] = static_cast<int>(class_outcomes[c].size() - slot_of[k][c].size());
      for (auto& [o, s] : slot_of[k][c]) slot_outcome_.push_back(o), s = slot++;
    }
  }
  union_begin_.push_back(slot);
  slot_base_.push_back(slot_base_.back() + slot);
  for (std::size_t r = 0; r < members_.size(); ++r)
    row_x_log_x_.push_back(sum_x_log_x(row_of(static_cast<int>(r)), O));
  block_begin_.resize(at(i + 1, 0, 0));
  for (int k = 0; k < K; ++k)
    for (int c = 0; c < classes; ++c) {
      block_begin_[at(i, k, c)] = blocks_.size();
      for (int r = member_begin_[k]; r < member_begin_[k + 1]; ++r)
        for (const auto& [o, s] : slot_of[k][c]) blocks_.push_back(row_of(r)[o] - base(r, c));
    }
}

double SparseGroupedEntropy::mean_exceptions() const {
  const std::size_t rows = classes_.size() * members_.size();
  return rows == 0 ? 0.0 : static_cast<double>(exceptions_) / static_cast<double>(rows);
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
  double term = 0.0;
  for (int c = 0; c < classes_[i]; ++c) {
    const double g = constant_[at(i, k, c)];
    if (g > 0.0) term += static_cast<double>(off_union_[at(i, k, c)]) * g * std::log(g);
  }
  return term;
}

double SparseGroupedEntropy::state_term(int i) const {
  return dot(member_belief_.data(), &row_x_log_x_[static_cast<std::size_t>(i) * live_],
             static_cast<std::size_t>(live_));
}

double SparseGroupedEntropy::outcome_term(int i) const {
  const int K = groups_, classes = classes_[i];
  const double* base = &base_[static_cast<std::size_t>(i) * members_.size() * kMaxClasses];
  double* slots = slots_.data() + slot_base_[i];
  // C[k][c] = Σ_{s in k} b(s) base(s, c) and their sums over groups, the part every T[o] =
  // Σ_k g[k][o] of class c has.
  double all[kMaxClasses] = {};
  for (int k = 0; k < K; ++k)
    for (int c = 0; c < classes; ++c) {
      double g = 0.0;
      for (int r = member_begin_[k]; r < member_begin_[k + 1]; ++r)
        g += member_belief_[r] * base[r * kMaxClasses + c];
      constant_[at(i, k, c)] = g;
      all[c] += g;
    }
  // g[k][o] = C[k][c] + the group's deltas, each sum in state order; T[o] adds what they add,
  // group by group.
  const int* class_of = &class_of_[static_cast<std::size_t>(i) * outcomes_];
  for (int o = 0; o < outcomes_; ++o) totals_[o] = all[class_of[o]];
  const int* outcome_of = &slot_outcome_[slot_base_[i]];
  for (int k = 0; k < K; ++k)
    for (int c = 0; c < classes; ++c) {
      const int begin = segment_begin_[at(i, k, c)];
      const int end = c + 1 < classes ? segment_begin_[at(i, k, c + 1)]
                                      : union_begin_[static_cast<std::size_t>(i) * (K + 1) + k + 1];
      sum_scaled_rows(&slots[begin], static_cast<std::size_t>(end - begin), constant_[at(i, k, c)],
                      &member_belief_[member_begin_[k]], &blocks_[block_begin_[at(i, k, c)]],
                      static_cast<std::size_t>(member_begin_[k + 1] - member_begin_[k]),
                      totals_.data(), &outcome_of[begin]);
    }
  // A probability of 0 can come out a rounding error below it: sum_x_log_x counts it 0.
  return sum_x_log_x(totals_.data(), static_cast<std::size_t>(outcomes_));
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
