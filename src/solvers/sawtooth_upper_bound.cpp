#include "solvers/sawtooth_upper_bound.h"

#include <algorithm>
#include <limits>

#include "solvers/alpha_vector_set.h"

namespace echoplan::solvers {

namespace {

// A new point must beat the current bound by more than rounding noise to be worth storing.
constexpr double kImprovement = 1e-12;
// The most a stored point's value may be raised to drop negligible states (reward units).
constexpr double kSupportSlack = 1e-10;

}  // namespace

SawtoothUpperBound::SawtoothUpperBound(std::vector<std::vector<double>> state_action_bounds,
                                       double value_span)
    : fib_vectors_(std::move(state_action_bounds)), value_span_(value_span) {
  const std::size_t S = fib_vectors_.front().size();
  corners_.assign(S, -std::numeric_limits<double>::infinity());
  for (const auto& q : fib_vectors_) {
    for (std::size_t s = 0; s < S; ++s) corners_[s] = std::max(corners_[s], q[s]);
  }
}

double SawtoothUpperBound::corner_value(const BeliefVector& belief) const {
  return dot(corners_, belief);
}

double SawtoothUpperBound::fib(const BeliefVector& belief) const {
  double best = -std::numeric_limits<double>::infinity();
  for (const auto& q : fib_vectors_) best = std::max(best, dot(q, belief));
  return best;
}

double SawtoothUpperBound::sawtooth(const BeliefVector& belief, double cv, int skip,
                                    double cap) const {
  double best = std::min(cv, cap);
  for (std::size_t i = 0; i < points_.size(); ++i) {
    if (static_cast<int>(i) == skip) continue;
    const Point& p = points_[i];
    // The point lowers the bound only where it lies below the corners, and then only when its
    // ratio exceeds `needed`: the scan over its support stops as soon as the ratio falls to it.
    const double gain = p.value - p.corner_value;
    if (gain >= 0.0) continue;
    const double needed = (best - cv) / gain;
    double ratio = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < p.support.size(); ++k) {
      ratio = std::min(ratio, belief[p.support[k]] * p.inverse[k]);
      if (ratio <= needed) break;
    }
    if (ratio > needed) best = cv + ratio * gain;
  }
  return best;
}

double SawtoothUpperBound::value(const BeliefVector& belief) const {
  return std::min(fib(belief), sawtooth(belief, corner_value(belief), -1,
                                        std::numeric_limits<double>::infinity()));
}

double SawtoothUpperBound::value_below(const BeliefVector& belief, double cap) const {
  return std::min(fib(belief), sawtooth(belief, corner_value(belief), -1, cap));
}

bool SawtoothUpperBound::add(const BeliefVector& belief, double v) {
  // Drop the smallest probabilities while the value they can carry stays within kSupportSlack:
  // V*(b~) <= V*(b) + value_span * dropped for b~ the renormalised rest (see header).
  std::vector<int> order;
  for (std::size_t s = 0; s < belief.size(); ++s) {
    if (belief[s] > 0.0) order.push_back(static_cast<int>(s));
  }
  std::sort(order.begin(), order.end(), [&](int a, int b) { return belief[a] < belief[b]; });
  double dropped = 0.0;
  std::size_t first_kept = 0;
  while (first_kept + 1 < order.size() &&
         (dropped + belief[order[first_kept]]) * value_span_ <= kSupportSlack) {
    dropped += belief[order[first_kept]];
    ++first_kept;
  }
  Point p;
  p.belief.assign(belief.size(), 0.0);
  for (std::size_t i = first_kept; i < order.size(); ++i) {
    p.belief[order[i]] = belief[order[i]] / (1.0 - dropped);
    p.support.push_back(order[i]);
    p.inverse.push_back(1.0 / p.belief[order[i]]);
  }
  p.value = v + value_span_ * dropped;

  // A corner: lower its value and refresh the points' cached corner values.
  if (p.support.size() == 1) {
    const int s = p.support.front();
    if (p.value >= corners_[s] - kImprovement) return false;
    corners_[s] = p.value;
    for (Point& q : points_) q.corner_value = corner_value(q.belief);
    return true;
  }
  if (p.value >= value(p.belief) - kImprovement) return false;
  p.corner_value = corner_value(p.belief);
  points_.push_back(std::move(p));
  // Prune when the set has doubled: amortised cost stays linear in the number of additions.
  if (points_.size() >= 2 * points_at_last_prune_ + 16) prune();
  return true;
}

void SawtoothUpperBound::prune() {
  // Remove one point at a time, each judged against the points still kept, so that two equal points
  // do not justify removing each other.
  for (std::size_t i = 0; i < points_.size();) {
    const Point& p = points_[i];
    const double without =
        std::min(fib(p.belief), sawtooth(p.belief, p.corner_value, static_cast<int>(i),
                                         std::numeric_limits<double>::infinity()));
    if (without <= p.value + kImprovement) {
      points_.erase(points_.begin() + static_cast<std::ptrdiff_t>(i));
    } else {
      ++i;
    }
  }
  points_at_last_prune_ = points_.size();
}

}  // namespace echoplan::solvers
