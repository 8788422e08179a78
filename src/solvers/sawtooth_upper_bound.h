// The upper bound on V*: the fast-informed-bound vectors, corner values and belief points, combined
// by the sawtooth interpolation (Hauskrecht 2000; as in HSVI2, Smith & Simmons 2005).
//
// Because V* is convex, a point (b_i, v_i) with v_i >= V*(b_i) and the corner values c(s) >=
// V*(e_s) bound V*(b) by  c.b + min_i [ (v_i - c.b_i) * min_{s: b_i(s) > 0} b(s) / b_i(s) ]. The
// FIB vectors (Hauskrecht 2000) give a second, convex bound max_a q_a . b; the value reported is
// the smaller.
//
// A point only helps beliefs whose support covers its own, so beliefs that are nearly on a face of
// the simplex (states with probability 1e-30 after many observations) would make useless points.
// Before storing, a point drops its negligible states and pays for it: moving mass d changes V* by
// at most d * value_span, where value_span bounds max_s alpha(s) - min_s alpha(s) for any policy.
#pragma once

#include <vector>

#include "solvers/alpha_vector_set.h"

namespace echoplan::solvers {

class SawtoothUpperBound {
 public:
  // `state_action_bounds[a][s]` >= Q*(s, a) for every belief at the corner e_s, as the fast
  // informed bound gives; terminal states must have 0. Corner values start at max_a of these.
  // `value_span` (reward units) bounds the spread of any policy's values over states, e.g. (max(0,
  // R_max) - min(0, R_min)) / (1 - discount).
  SawtoothUpperBound(std::vector<std::vector<double>> state_action_bounds, double value_span);

  double value(const BeliefVector& belief) const;
  // min(value(belief), cap), faster when the cap is low: points that cannot go below it are
  // skipped after a partial scan.
  double value_below(const BeliefVector& belief, double cap) const;

  // Records that V*(belief) <= value. Corners (one state with probability 1) lower that corner's
  // value; other beliefs become points when they improve the bound. Returns true when the bound
  // changed.
  bool add(const BeliefVector& belief, double value);

  // Removes points that the others (and the corners and FIB vectors) already imply.
  void prune();

  std::size_t num_points() const { return points_.size(); }

 private:
  struct Point {
    BeliefVector belief;
    std::vector<int> support;     // states with belief > 0
    std::vector<double> inverse;  // [k] = 1 / belief[support[k]]: a multiplication per state
    double value = 0.0;
    double corner_value = 0.0;  // corners_ . belief, refreshed when a corner changes
  };
  double corner_value(const BeliefVector& belief) const;
  // The sawtooth bound from the corners and every point except `skip` (-1 for none).
  // Never above `cap` (+inf for the plain bound).
  double sawtooth(const BeliefVector& belief, double corner_value_at_belief, int skip,
                  double cap) const;
  double fib(const BeliefVector& belief) const;

  std::vector<std::vector<double>> fib_vectors_;  // [a][s]
  double value_span_ = 0.0;
  std::vector<double> corners_;  // [s]
  std::vector<Point> points_;
  std::size_t points_at_last_prune_ = 0;
};

}  // namespace echoplan::solvers
