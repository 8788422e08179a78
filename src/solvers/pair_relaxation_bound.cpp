#include "solvers/pair_relaxation_bound.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace echoplan::solvers {

namespace {

// Log-odds of s in (0, 0.5], accurate for tiny s.
double log_odds(double s) { return std::log(s) - std::log1p(-s); }

}  // namespace

// The grid is kept as two halves that meet at p = 1/2: the lower half holds p = s_k, the upper
// half p = 1 - s_k, with s_0 = 0 < s_1 < ... < s_H = 1/2 evenly spaced in log-odds from s_1 on.
// A belief near 1 is then located by its small complement q = 1 - p (computed from the masses,
// not as 1 - p, which would lose it to rounding), so both ends are resolved alike. Values are
// stored flat: [k] for p = s_k, [H + 1 + k] for p = 1 - s_k; interpolation is linear in p inside
// each half, which is linear in q in the upper one.

PairRelaxationBound::PairRelaxationBound(const IdentificationTables& t,
                                         const PairRelaxationOptions& o)
    : live_states_(t.live_states), known_value_(t.known_value) {
  if (o.grid_points < 5 || o.max_log_odds <= 0.0)
    throw std::invalid_argument("pair relaxation: grid too small");
  const int half = (o.grid_points + 1) / 2;  // s_1 .. s_H
  grid_.assign(half + 1, 0.0);
  log_odds_min_ = -o.max_log_odds;
  log_odds_step_ = o.max_log_odds / (half - 1);
  for (int k = 1; k <= half; ++k) {
    const double x = log_odds_min_ + (k - 1) * log_odds_step_;
    grid_[k] = 1.0 / (1.0 + std::exp(-x));
  }
  grid_[half] = 0.5;

  const int L = t.live_states, O = t.observations, A = t.actions;
  // Candidate pairs: those whose value is not the corners' chord, the most confusable first
  // (the largest Bhattacharyya coefficient of their observation rows under any sensing action).
  struct Candidate {
    int i, j;
    double confusability;
  };
  std::vector<Candidate> candidates;
  for (int i = 0; i < L; ++i) {
    for (int j = i + 1; j < L; ++j) {
      bool linear = false;
      double confusability = 0.0;
      for (int a = 0; a < A; ++a) {
        if (t.terminal[a]) {
          if (t.reward[a * L + i] >= known_value_[i] && t.reward[a * L + j] >= known_value_[j])
            linear = true;
          continue;
        }
        double c = 0.0;
        for (int o2 = 0; o2 < O; ++o2) {
          const std::size_t row = (std::size_t(a) * O + o2) * L;
          c += std::sqrt(t.emission[row + i] * t.emission[row + j]);
        }
        confusability = std::max(confusability, c);
      }
      if (!linear) candidates.push_back({i, j, confusability});
    }
  }
  std::stable_sort(
      candidates.begin(), candidates.end(),
      [](const Candidate& x, const Candidate& y) { return x.confusability > y.confusability; });
  if (candidates.size() > o.max_pairs) candidates.resize(o.max_pairs);
  for (const Candidate& c : candidates) {
    Pair pair;
    pair.i = c.i;
    pair.j = c.j;
    solve(pair, t, o);
    pairs_.push_back(std::move(pair));
  }
}

void PairRelaxationBound::locate(double s, int& cell, double& weight) const {
  locate(s, s > 0.0 ? log_odds(s) : 0.0, cell, weight);
}

void PairRelaxationBound::locate(double s, double x, int& cell, double& weight) const {
  const int half = static_cast<int>(grid_.size()) - 1;
  if (s <= grid_[1]) {
    cell = 0;
    weight = s / grid_[1];
    return;
  }
  if (s >= grid_[half]) {
    cell = half - 1;
    weight = 1.0;
    return;
  }
  int k = 1 + static_cast<int>(std::floor((x - log_odds_min_) / log_odds_step_));
  k = std::clamp(k, 1, half - 1);
  // The log-odds arithmetic can be off by one cell at rounding; the grid itself decides.
  while (k > 1 && grid_[k] > s) --k;
  while (k < half - 1 && grid_[k + 1] < s) ++k;
  cell = k;
  weight = std::clamp((s - grid_[k]) / (grid_[k + 1] - grid_[k]), 0.0, 1.0);
}

void PairRelaxationBound::solve(Pair& pair, const IdentificationTables& t,
                                const PairRelaxationOptions& o) const {
  const int L = t.live_states, O = t.observations, A = t.actions;
  const int half = static_cast<int>(grid_.size()) - 1;
  const int points = 2 * (half + 1);
  const int i = pair.i, j = pair.j;
  // Point n's (p, q): lower half p = s_k, q = 1 - s_k; upper half the other way round.
  auto masses = [&](int n, double& p, double& q) {
    const int k = n <= half ? n : n - half - 1;
    const double s = grid_[k];
    p = n <= half ? s : 1.0 - s;
    q = n <= half ? 1.0 - s : s;
  };
  // Start from the chord: V*_ij(p) <= p K_i + (1 - p) K_j (the state revealed at once).
  pair.values.resize(points);
  for (int n = 0; n < points; ++n) {
    double p, q;
    masses(n, p, q);
    pair.values[n] = p * known_value_[i] + q * known_value_[j];
  }
  // Each sensing action's successors of every point, fixed: (probability, left index, weight of
  // the right one).
  struct Step {
    double probability, weight;
    int left;
  };
  std::vector<int> sensing;
  for (int a = 0; a < A; ++a)
    if (!t.terminal[a]) sensing.push_back(a);
  std::vector<Step> steps(std::size_t(points) * sensing.size() * O);
  std::vector<double> commit(points), sense_reward(std::size_t(points) * sensing.size());
  for (int n = 0; n < points; ++n) {
    double p, q;
    masses(n, p, q);
    commit[n] = -std::numeric_limits<double>::infinity();
    for (int a = 0; a < A; ++a)
      if (t.terminal[a])
        commit[n] = std::max(commit[n], p * t.reward[a * L + i] + q * t.reward[a * L + j]);
    for (std::size_t x = 0; x < sensing.size(); ++x) {
      const int a = sensing[x];
      sense_reward[n * sensing.size() + x] = p * t.reward[a * L + i] + q * t.reward[a * L + j];
      for (int ob = 0; ob < O; ++ob) {
        const std::size_t row = (std::size_t(a) * O + ob) * L;
        const double pi = p * t.emission[row + i], qj = q * t.emission[row + j];
        Step& step = steps[(n * sensing.size() + x) * O + ob];
        step = Step{pi + qj, 0.0, 0};
        if (step.probability <= 0.0) continue;
        const double p2 = pi / step.probability, q2 = qj / step.probability;
        int cell;
        if (p2 <= q2) {
          locate(p2, cell, step.weight);
          step.left = cell;
        } else {
          locate(q2, cell, step.weight);
          step.left = half + 1 + cell;
        }
      }
    }
  }
  // Gauss-Seidel sweeps; the ends (p = 0, p = 1: the state known) stay at the known values.
  for (int sweep = 0; sweep < o.max_iterations; ++sweep) {
    double change = 0.0;
    for (int n = 0; n < points; ++n) {
      if (n == 0 || n == half + 1) continue;
      double best = commit[n];
      for (std::size_t x = 0; x < sensing.size(); ++x) {
        double q = sense_reward[n * sensing.size() + x];
        const Step* s = &steps[(n * sensing.size() + x) * O];
        for (int ob = 0; ob < O; ++ob) {
          if (s[ob].probability <= 0.0) continue;
          const double* v = &pair.values[s[ob].left];
          q += t.discount * s[ob].probability * (v[0] + s[ob].weight * (v[1] - v[0]));
        }
        best = std::max(best, q);
      }
      // Both the old and the new value bound V*_ij from above; keep the smaller.
      if (best < pair.values[n]) {
        change = std::max(change, pair.values[n] - best);
        pair.values[n] = best;
      }
    }
    if (change <= o.tolerance) break;
  }
}

double PairRelaxationBound::pair_value(std::size_t index, double p) const {
  const Pair& pair = pairs_.at(index);
  const int half = static_cast<int>(grid_.size()) - 1;
  int cell;
  double w;
  if (p <= 0.5) {
    locate(p, cell, w);
  } else {
    locate(1.0 - p, cell, w);
    cell += half + 1;
  }
  const double* v = &pair.values[cell];
  return v[0] + w * (v[1] - v[0]);
}

double PairRelaxationBound::value(const double* b) const {
  double corners = 0.0;
  for (int l = 0; l < live_states_; ++l) corners += b[l] * known_value_[l];
  if (pairs_.empty()) return corners;
  const int half = static_cast<int>(grid_.size()) - 1;
  saving_scratch_.resize(pairs_.size());
  order_scratch_.clear();
  // A pair's log-odds is a difference of two of these: one logarithm per state, not per pair.
  log_scratch_.resize(live_states_);
  for (int l = 0; l < live_states_; ++l) log_scratch_[l] = b[l] > 0.0 ? std::log(b[l]) : 0.0;
  for (std::size_t x = 0; x < pairs_.size(); ++x) {
    const Pair& pair = pairs_[x];
    saving_scratch_[x] = 0.0;
    // With either mass 0 the pair's value is the corners' (the state known): nothing saved.
    if (b[pair.i] <= 0.0 || b[pair.j] <= 0.0) continue;
    const double m = b[pair.i] + b[pair.j];
    const double p = b[pair.i] / m, q = b[pair.j] / m;
    const double log_odds_p = log_scratch_[pair.i] - log_scratch_[pair.j];
    int cell;
    double w;
    if (p <= q) {
      locate(p, log_odds_p, cell, w);
    } else {
      locate(q, -log_odds_p, cell, w);
      cell += half + 1;
    }
    const double* v = &pair.values[cell];
    const double saving =
        m * (p * known_value_[pair.i] + q * known_value_[pair.j] - (v[0] + w * (v[1] - v[0])));
    if (saving > 0.0) {
      saving_scratch_[x] = saving;
      order_scratch_.push_back(static_cast<int>(x));
    }
  }
  // Greedy matching by saving: any set of disjoint pairs gives a valid bound.
  std::sort(order_scratch_.begin(), order_scratch_.end(),
            [&](int x, int y) { return saving_scratch_[x] > saving_scratch_[y]; });
  used_scratch_.assign(live_states_, 0);
  double saved = 0.0;
  for (int x : order_scratch_) {
    const Pair& pair = pairs_[x];
    if (used_scratch_[pair.i] || used_scratch_[pair.j]) continue;
    used_scratch_[pair.i] = used_scratch_[pair.j] = 1;
    saved += saving_scratch_[x];
  }
  return corners - saved;
}

}  // namespace echoplan::solvers
