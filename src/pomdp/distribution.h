// Small helpers for discrete probability distributions, shared by the models and the loaders so
// that "a row sums to 1" means the same thing everywhere (within kProbabilityTolerance = 1e-6).
#pragma once

#include <cmath>
#include <cstddef>

namespace echoplan::pomdp {

// Tolerance on a probability row's sum, and on entries just above 1 from rounding.
inline constexpr double kProbabilityTolerance = 1e-6;

// What is wrong with a row of probabilities, if anything.
struct RowCheck {
  double sum = 0.0;
  bool in_range = true;  // every entry in [0, 1 + tolerance] (and not NaN)
  bool ok() const { return in_range && std::abs(sum - 1.0) <= kProbabilityTolerance; }
};

inline RowCheck check_row(const double* p, std::size_t n) {
  RowCheck c;
  for (std::size_t i = 0; i < n; ++i) {
    if (!(p[i] >= 0.0 && p[i] <= 1.0 + kProbabilityTolerance)) c.in_range = false;
    c.sum += p[i];
  }
  return c;
}

// Index drawn from probabilities p[0..n-1] (summing to 1) with one uniform draw u in [0, 1).
// When rounding leaves u above the running sum, the last index with mass is returned.
inline int sample_index(const double* p, int n, double u) {
  double acc = 0.0;
  for (int i = 0; i < n - 1; ++i) {
    acc += p[i];
    if (u < acc) return i;
  }
  for (int i = n - 1; i > 0; --i) {
    if (p[i] > 0.0) return i;
  }
  return 0;
}

// The same draw from precomputed cumulative sums cdf[i] = p[0] + ... + p[i].
inline int sample_from_cdf(const double* cdf, int n, double u) {
  for (int i = 0; i < n - 1; ++i) {
    if (u < cdf[i]) return i;
  }
  return n - 1;
}

}  // namespace echoplan::pomdp
