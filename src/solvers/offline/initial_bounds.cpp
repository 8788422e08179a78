#include "solvers/offline/initial_bounds.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace echoplan::solvers::offline {

namespace {

// min and max of the non-terminal rewards, widened to include 0 (terminal states earn 0 forever).
std::pair<double, double> reward_range(const FlatPomdp& pomdp) {
  double lo = 0.0, hi = 0.0;
  for (double r : pomdp.reward) {
    lo = std::min(lo, r);
    hi = std::max(hi, r);
  }
  return {lo, hi};
}

}  // namespace

double value_span(const FlatPomdp& pomdp) {
  const auto [lo, hi] = reward_range(pomdp);
  return (hi - lo) / (1.0 - pomdp.discount);
}

std::vector<AlphaVector> blind_policy_vectors(const FlatPomdp& pomdp,
                                              const InitialBoundOptions& options) {
  const int S = pomdp.num_states;
  const double g = pomdp.discount;
  const double start = reward_range(pomdp).first / (1.0 - g);
  std::vector<AlphaVector> out;
  for (int a = 0; a < pomdp.num_actions; ++a) {
    // From start <= V_blind, the blind Bellman operator increases monotonically toward V_blind.
    std::vector<double> alpha(S), next(S);
    for (int s = 0; s < S; ++s) alpha[s] = pomdp.terminal[s] ? 0.0 : start;
    for (int it = 0; it < options.max_iterations; ++it) {
      double change = 0.0;
      for (int s = 0; s < S; ++s) {
        if (pomdp.terminal[s]) {
          next[s] = 0.0;
          continue;
        }
        double future = 0.0;
        for (const Successor& n : pomdp.successors_of(s, a))
          future += n.probability * alpha[n.state];
        next[s] = pomdp.reward_at(s, a) + g * future;
        change = std::max(change, std::abs(next[s] - alpha[s]));
      }
      alpha.swap(next);
      if (change <= options.tolerance) break;
    }
    out.push_back({a, std::move(alpha)});
  }
  return out;
}

std::vector<std::vector<double>> fast_informed_bound(const FlatPomdp& pomdp,
                                                     const InitialBoundOptions& options) {
  const int S = pomdp.num_states, A = pomdp.num_actions, O = pomdp.num_observations;
  const double g = pomdp.discount;
  const double start = reward_range(pomdp).second / (1.0 - g);
  // From start >= Q_FIB, the FIB operator decreases monotonically toward Q_FIB.
  std::vector<std::vector<double>> q(A, std::vector<double>(S)), next = q;
  for (int a = 0; a < A; ++a) {
    for (int s = 0; s < S; ++s) q[a][s] = pomdp.terminal[s] ? 0.0 : start;
  }
  std::vector<double> per_next_action(A);
  for (int it = 0; it < options.max_iterations; ++it) {
    double change = 0.0;
    for (int a = 0; a < A; ++a) {
      for (int s = 0; s < S; ++s) {
        if (pomdp.terminal[s]) {
          next[a][s] = 0.0;
          continue;
        }
        double future = 0.0;
        for (int o = 0; o < O; ++o) {
          std::fill(per_next_action.begin(), per_next_action.end(), 0.0);
          bool reachable = false;
          for (const Successor& n : pomdp.successors_of(s, a)) {
            const double w = n.probability * pomdp.observation_row(a, n.state)[o];
            if (w == 0.0) continue;
            reachable = true;
            for (int a2 = 0; a2 < A; ++a2) per_next_action[a2] += w * q[a2][n.state];
          }
          if (reachable)
            future += *std::max_element(per_next_action.begin(), per_next_action.end());
        }
        next[a][s] = pomdp.reward_at(s, a) + g * future;
        change = std::max(change, std::abs(next[a][s] - q[a][s]));
      }
    }
    q.swap(next);
    if (change <= options.tolerance) break;
  }
  return q;
}

}  // namespace echoplan::solvers::offline
