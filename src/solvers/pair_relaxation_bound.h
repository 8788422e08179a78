// An upper bound on V* for identification problems (the hidden state fixed until a terminal
// action ends the episode) from two-state sub-problems: the partition relaxation.
//
// Telling the agent which block of a partition of the states holds can only raise its value, so
// for any partition into blocks B
//   V*(b) <= Σ_B P(B) · V*_B(b | B),
// where V*_B is the value of the same problem with its belief restricted to B. With blocks of one
// state V*_B is the known-state value K(s) (the "one more sensing reveals the state" corner); with
// blocks of two states {i, j} it is a function of one number, p = P(i | {i, j}), solved once, up
// front, on a grid. The bound at a belief pairs up states greedily by what pairing saves over the
// corners, m_ij · (p K_i + (1 − p) K_j − V*_ij(p)) with m_ij = b_i + b_j; any set of disjoint
// pairs gives a valid bound, so the greedy matching is sound (the best matching would be tighter).
//
// The two-state values: value iteration on a grid over p (dense near 0 and 1, where long runs of
// observations take the belief), each grid value backed up with the values between grid points
// interpolated linearly in p, started from the corners' chord (an upper bound). A linear
// interpolation of values that bound a convex function from above at the grid points bounds it
// from above everywhere between them (V* is convex, Lovejoy 1991; Hauskrecht 2000, section 5,
// "grid-based interpolation upper bounds"), so every backup keeps every grid value >= V*_ij at its
// point, whatever the order and however many iterations run: the bound is sound at any stop.
// Iterating makes it tighter, down to the interpolation's resolution.
#pragma once

#include <cstddef>
#include <vector>

#include "solvers/identification_tables.h"

namespace echoplan::solvers {

struct PairRelaxationOptions {
  // Grid points strictly between 0 and 1, spaced evenly in log-odds over ±max_log_odds.
  int grid_points = 2001;
  double max_log_odds = 36.0;
  // Value iteration stops when no grid value moved by more than this (reward units), or after
  // max_iterations sweeps; either way the values are upper bounds.
  double tolerance = 1e-10;
  int max_iterations = 20000;
  // At most this many pairs are solved (the most confusable first); pairs whose value is the
  // corners' chord (one terminal action earns both known values) are never stored.
  // 64: the setup grows with pairs · observations (64 objects, 65 observations: 256 pairs took
  // 14 s, 64 pairs about a quarter of that; 8 objects: 20 pairs, 60 ms).
  std::size_t max_pairs = 64;
};

class PairRelaxationBound {
 public:
  PairRelaxationBound() = default;
  PairRelaxationBound(const IdentificationTables& tables,
                      const PairRelaxationOptions& options = {});

  // An upper bound on V*(b) for b over the live states (normalised). Without pairs: Σ b(l) K(l).
  double value(const double* belief) const;
  // V*_ij(p) bounded from above, p = P(i | {i, j}); for the stored pair with index `pair`.
  double pair_value(std::size_t pair, double p) const;

  std::size_t num_pairs() const { return pairs_.size(); }
  int first_state(std::size_t pair) const { return pairs_[pair].i; }
  int second_state(std::size_t pair) const { return pairs_[pair].j; }

 private:
  struct Pair {
    int i = 0, j = 0;
    std::vector<double> values;  // [k] at grid_[k]; values[0] = K_j (p = 0), back = K_i (p = 1)
  };
  // Interpolation cell of p: the index k with grid_[k] <= p <= grid_[k + 1] and the weight of
  // k + 1.
  void locate(double p, int& cell, double& weight) const;
  // The same with p's log-odds given (p in (0, 1/2]).
  void locate(double p, double log_odds, int& cell, double& weight) const;
  void solve(Pair& pair, const IdentificationTables& t, const PairRelaxationOptions& o) const;

  int live_states_ = 0;
  std::vector<double> known_value_;
  // s_0 = 0 < s_1 < ... < s_H = 1/2, s_1..s_H evenly spaced in log-odds; the grid's p values are
  // the s_k and the 1 - s_k (see the .cpp).
  std::vector<double> grid_;
  double log_odds_min_ = 0.0, log_odds_step_ = 1.0;
  std::vector<Pair> pairs_;
  mutable std::vector<double> saving_scratch_;
  mutable std::vector<double> log_scratch_;
  mutable std::vector<int> order_scratch_;
  mutable std::vector<char> used_scratch_;
};

}  // namespace echoplan::solvers
