// An independent reference for the identification solver's tests: V*(b) bracketed by a
// finite-horizon search over every (action, observation) count vector up to a depth, written
// directly over the raw tables (no code shared with the solver). Leaves are bounded below by the
// best terminal action now and above by Σ_s b(s) K(s), K(s) = max(0, best sensing reward) / (1 − γ)
// + max(0, best terminal reward): no plan earns more from a known state. Only for problems without
// collisions (every sensing action keeps every live state).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <unordered_map>
#include <vector>

#include "pomdp/model.h"
#include "solvers/identification_solver.h"

namespace echoplan::solvers::testing {

class BruteForceValue {
 public:
  BruteForceValue(const pomdp::TabularModel& m, int depth) : m_(m), depth_(depth) {
    const int S = m.num_states();
    known_.assign(S, 0.0);
    for (int s = 0; s < S; ++s) {
      double sense = 0.0, commit = 0.0;
      for (int a = 0; a < m.num_actions(); ++a) {
        if (m.transition(s, a, s) > 0.0 && !m.terminal(s))
          sense = std::max(sense, m.reward(s, a));
        else
          commit = std::max(commit, m.reward(s, a));
      }
      known_[s] = sense / (1.0 - m.discount()) + commit;
    }
    // A count vector is memoised as one number: the counts of the sensing actions' pairs as digits
    // in base depth + 1 (no count exceeds the depth).
    std::uint64_t weight = 1;
    digit_.assign(std::size_t(m.num_actions()) * m.num_observations(), 0);
    for (int a = 0; a < m.num_actions(); ++a) {
      sensing_.push_back(keeps_state(a));
      if (!sensing_.back()) continue;
      for (int o = 0; o < m.num_observations(); ++o) {
        digit_[std::size_t(a) * m.num_observations() + o] = weight;
        if (weight > std::numeric_limits<std::uint64_t>::max() / std::uint64_t(depth + 1))
          throw std::invalid_argument("brute force: too many count vectors to number");
        weight *= std::uint64_t(depth + 1);
      }
    }
  }

  // Bounds on V*(b) (b over all model states).
  Bounds value(const std::vector<double>& b) {
    memo_.clear();
    return search(b, 0, depth_);
  }

 private:
  bool keeps_state(int a) const {
    for (int s = 0; s < m_.num_states(); ++s)
      if (!m_.terminal(s) && m_.transition(s, a, s) < 1.0) return false;
    return true;
  }
  Bounds search(const std::vector<double>& b, std::uint64_t counts, int depth) {
    if (auto it = memo_.find(counts); it != memo_.end()) return it->second;
    const int S = m_.num_states(), O = m_.num_observations();
    auto expected = [&](int a) {
      double r = 0.0;
      for (int s = 0; s < S; ++s) r += b[s] * m_.reward(s, a);
      return r;
    };
    double commit = -std::numeric_limits<double>::infinity();
    for (int a = 0; a < m_.num_actions(); ++a)
      if (!sensing_[a]) commit = std::max(commit, expected(a));
    Bounds best{commit, commit};
    if (depth == 0) {
      double upper = 0.0;
      for (int s = 0; s < S; ++s) upper += b[s] * known_[s];
      best.upper = std::max(commit, upper);
      return memo_[counts] = best;
    }
    for (int a = 0; a < m_.num_actions(); ++a) {
      if (!sensing_[a]) continue;
      Bounds q{expected(a), expected(a)};
      for (int o = 0; o < O; ++o) {
        std::vector<double> next(S, 0.0);
        double p = 0.0;
        for (int s = 0; s < S; ++s) p += next[s] = b[s] * m_.observation(a, s, o);
        if (p <= 0.0) continue;
        for (double& x : next) x /= p;
        const Bounds child = search(next, counts + digit_[std::size_t(a) * O + o], depth - 1);
        q.lower += m_.discount() * p * child.lower;
        q.upper += m_.discount() * p * child.upper;
      }
      best.lower = std::max(best.lower, q.lower);
      best.upper = std::max(best.upper, q.upper);
    }
    return memo_[counts] = best;
  }

  const pomdp::TabularModel& m_;
  int depth_;
  std::vector<double> known_;
  std::vector<bool> sensing_;         // [a]: keeps every live state
  std::vector<std::uint64_t> digit_;  // [a * O + o]: what one more (a, o) adds to the number
  std::unordered_map<std::uint64_t, Bounds> memo_;
};

}  // namespace echoplan::solvers::testing
