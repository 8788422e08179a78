#include "solvers/readings_left_bound.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <utility>

namespace echoplan::solvers {

namespace {
// A stay probability this close to 1 is no collision (the tables' sums carry rounding).
constexpr double kCertain = 1.0 - 1e-12;
// An open node whose known-state value is this close to its best sort is not worth expanding.
constexpr double kNoSlack = 1e-12;
}  // namespace

ReadingsLeftBound::ReadingsLeftBound(std::shared_ptr<const IdentificationTables> tables,
                                     const ReadingsLeftOptions& options)
    : tables_(std::move(tables)), options_(options) {
  const IdentificationTables& t = *tables_;
  const int L = t.live_states;
  applies_ = t.limits.any();
  for (int a = 0; a < t.actions; ++a) {
    if (t.terminal[a]) {
      terminals_.push_back(a);
      continue;
    }
    sensing_.push_back(a);
    if (t.limits.max_uses(a) <= 0) applies_ = false;
    for (int l = 0; l < L; ++l)
      if (t.reward[a * L + l] > 0.0 || t.stay[a * L + l] < kCertain) applies_ = false;
  }
}

double ReadingsLeftBound::best_sort(const double* w) const {
  double floor = 0.0, best = 0.0;  // every bonus is >= 0, so the best is too
  for (std::size_t i = 0; i < support_.size(); ++i) floor += w[i] * floor_[i];
  for (std::size_t c = 0; c + 1 < bonus_start_.size(); ++c) {
    double bonus = 0.0;
    for (std::size_t k = bonus_start_[c]; k < bonus_start_[c + 1]; ++k)
      bonus += w[bonus_[k].first] * bonus_[k].second;
    best = std::max(best, bonus);
  }
  return floor + best;
}

double ReadingsLeftBound::known(const double* w) const {
  double v = 0.0;
  for (std::size_t i = 0; i < support_.size(); ++i) v += w[i] * known_[i];
  return v;
}

double ReadingsLeftBound::told_all_value(const double* w0) const {
  const std::size_t S = support_.size(), K = readings_.size();
  const int O = tables_->observations;
  nodes_.assign(w0, w0 + S);
  node_level_.assign(1, 0);
  // Open nodes by slack (known-state value minus best sort): a max-heap of (slack, node).
  std::vector<std::pair<double, int>> open{{known(w0) - best_sort(w0), 0}};
  double resolved = 0.0;  // the leaves' exact values
  scratch_.resize(S);
  for (int expansions = 0; expansions < options_.budget && !open.empty(); ++expansions) {
    if (open.front().first <= kNoSlack) break;
    std::pop_heap(open.begin(), open.end());
    const int n = open.back().second;
    open.pop_back();
    const int level = node_level_[n];
    const double* e_action = &emission_[std::size_t(readings_[level]) * O * S];
    std::copy_n(&nodes_[std::size_t(n) * S], S, scratch_.begin());
    for (int o = 0; o < O; ++o) {
      const double* e = e_action + std::size_t(o) * S;
      const std::size_t child = nodes_.size();
      double mass = 0.0;
      for (std::size_t i = 0; i < S; ++i) mass += scratch_[i] * e[i];
      if (mass <= 0.0) continue;
      nodes_.resize(child + S);
      double* w = &nodes_[child];
      for (std::size_t i = 0; i < S; ++i) w[i] = scratch_[i] * e[i];
      if (std::size_t(level) + 1 == K) {
        resolved += best_sort(w);  // every reading heard: the sort is chosen knowing them all
        nodes_.resize(child);
        continue;
      }
      node_level_.push_back(level + 1);
      open.emplace_back(known(w) - best_sort(w), int(child / S));
      std::push_heap(open.begin(), open.end());
    }
  }
  for (const auto& [slack, n] : open) resolved += known(&nodes_[std::size_t(n) * S]);
  return resolved;
}

double ReadingsLeftBound::relaxed(int terminal, int l, double discount_left) const {
  const IdentificationTables& t = *tables_;
  const double r = t.reward[terminal * t.live_states + l];
  return r >= 0.0 ? t.discount * r : discount_left * r;
}

double ReadingsLeftBound::read_support(const double* b, double discount_left) const {
  const int L = tables_->live_states;
  support_.resize(L);
  std::iota(support_.begin(), support_.end(), 0);
  std::stable_sort(support_.begin(), support_.end(), [&](int x, int y) { return b[x] > b[y]; });
  std::size_t S = 0;
  while (S < support_.size() && int(S) < options_.max_support &&
         b[support_[S]] >= options_.min_probability)
    ++S;
  double tail = 0.0;
  known_.assign(S, -std::numeric_limits<double>::infinity());
  for (std::size_t i = 0; i < support_.size(); ++i) {
    double best = -std::numeric_limits<double>::infinity();
    for (int a : terminals_) best = std::max(best, relaxed(a, support_[i], discount_left));
    if (i < S)
      known_[i] = best;
    else
      tail += b[support_[i]] * best;
  }
  support_.resize(S);
  return tail;
}

void ReadingsLeftBound::read_sorts(double discount_left) const {
  // Each distinct sort once, as a floor per state (the least any sort earns there) plus each
  // sort's bonus above it where it has one: a sort that pays more only in its own state costs one
  // entry, not one per state.
  const std::size_t S = support_.size();
  columns_.resize(terminals_.size());
  for (std::size_t k = 0; k < terminals_.size(); ++k) {
    columns_[k].resize(S);
    for (std::size_t i = 0; i < S; ++i)
      columns_[k][i] = relaxed(terminals_[k], support_[i], discount_left);
  }
  std::sort(columns_.begin(), columns_.end());
  const auto distinct = std::unique(columns_.begin(), columns_.end());
  floor_.assign(S, std::numeric_limits<double>::infinity());
  for (auto c = columns_.begin(); c != distinct; ++c)
    for (std::size_t i = 0; i < S; ++i) floor_[i] = std::min(floor_[i], (*c)[i]);
  bonus_.clear();
  bonus_start_.assign(1, 0);
  for (auto c = columns_.begin(); c != distinct; ++c) {
    for (std::size_t i = 0; i < S; ++i)
      if ((*c)[i] > floor_[i]) bonus_.emplace_back(int(i), (*c)[i] - floor_[i]);
    bonus_start_.push_back(bonus_.size());
  }
}

void ReadingsLeftBound::read_readings(const std::uint16_t* uses) const {
  // Most informative over the support first (the best-first search then resolves the likeliest
  // beliefs sooner). Each action with readings left gets a slot of emissions over the support; a
  // reading is its action's slot.
  const IdentificationTables& t = *tables_;
  const int L = t.live_states, O = t.observations;
  const std::size_t S = support_.size();
  emission_.clear();
  std::vector<std::pair<double, int>> scored;  // (−informativeness, slot)
  for (int a : sensing_) {
    const int n = t.limits.max_uses(a) - (uses == nullptr ? 0 : int(uses[a]));
    if (n <= 0) continue;
    const int slot = int(emission_.size() / (std::size_t(O) * S));
    double score = 0.0;
    for (int o = 0; o < O; ++o) {
      double most = 0.0;
      for (std::size_t i = 0; i < S; ++i) {
        const double e = t.emission[(std::size_t(a) * O + o) * L + support_[i]];
        emission_.push_back(e);
        most = std::max(most, e);
      }
      score += most;
    }
    for (int k = 0; k < n; ++k) scored.emplace_back(-score, slot);
  }
  std::stable_sort(scored.begin(), scored.end());
  readings_.clear();
  for (const auto& [score, slot] : scored) readings_.push_back(slot);
}

double ReadingsLeftBound::value(const double* b, const std::uint16_t* uses) const {
  if (!applies_) return std::numeric_limits<double>::infinity();
  const IdentificationTables& t = *tables_;
  const int L = t.live_states;
  const UseLimits& limits = t.limits;
  auto used = [&](int a) { return uses == nullptr ? 0 : int(uses[a]); };
  auto expected = [&](int a) {
    double r = 0.0;
    for (int l = 0; l < L; ++l) r += b[l] * t.reward[a * L + l];
    return r;
  };
  double commit = -std::numeric_limits<double>::infinity();
  for (int a : terminals_) commit = std::max(commit, expected(a));
  double first = -std::numeric_limits<double>::infinity();  // the best first sensing's reward
  int left = 0;
  for (int a : sensing_) {
    left += std::max(0, limits.max_uses(a) - used(a));
    if (limits.allows_after(used, a)) first = std::max(first, expected(a));
  }
  if (left == 0 || first == -std::numeric_limits<double>::infinity()) return commit;
  if (left > options_.max_readings) return std::numeric_limits<double>::infinity();

  const double discount_left = std::pow(t.discount, left);  // a wrong sort's least discount
  const double tail = read_support(b, discount_left);
  const std::size_t S = support_.size();
  if (S == 0) return std::max(commit, first + tail);
  read_sorts(discount_left);
  read_readings(uses);
  std::vector<double> w(S);
  for (std::size_t i = 0; i < S; ++i) w[i] = b[support_[i]];
  return std::max(commit, first + told_all_value(w.data()) + tail);
}

}  // namespace echoplan::solvers
