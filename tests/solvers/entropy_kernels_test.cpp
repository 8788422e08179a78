// The policy leaf's vectorised kernels against the plain loops they stand for: the sums of
// products bit for bit (the callers rely on it to leave every trial unchanged), x log x to
// rounding.
#include "solvers/entropy_kernels.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <vector>

#include "common/rng.h"

namespace echoplan::solvers {
namespace {

std::vector<double> draws(std::size_t n, Rng& rng) {
  std::vector<double> x(n);
  for (double& v : x) v = uniform01(rng) * 2.0 - 0.5;
  return x;
}

bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

TEST(EntropyKernels, SumScaledRowsAndWhatTheyAddToTheTotalsAreTheScalarLoopsBitForBit) {
  Rng rng(11);
  // Widths below, at and past a vector's length (eight, then four), and odd ones (a remainder
  // after the vectors).
  for (std::size_t n : {1u, 3u, 4u, 8u, 12u, 13u, 16u, 37u}) {
    for (std::size_t count : {1u, 5u, 9u}) {
      const std::vector<double> rows = draws(n * count, rng);
      std::vector<double> scales = draws(count, rng);
      scales[0] = 0.0;  // a ruled-out state adds an exact 0
      const double start = 0.3;
      std::vector<double> expected(n, start), got(n, -1.0);
      for (std::size_t r = 0; r < count; ++r)
        for (std::size_t i = 0; i < n; ++i) {
          const double product = scales[r] * rows[r * n + i];
          expected[i] = expected[i] + product;
        }
      // Column i's total is totals[n - 1 - i], which starts at i.
      std::vector<int> total_of(n);
      std::vector<double> totals(n), expected_totals(n);
      for (std::size_t i = 0; i < n; ++i) {
        total_of[i] = static_cast<int>(n - 1 - i);
        totals[n - 1 - i] = static_cast<double>(i);
        expected_totals[n - 1 - i] = static_cast<double>(i) + (expected[i] - start);
      }
      sum_scaled_rows(got.data(), n, start, scales.data(), rows.data(), count, totals.data(),
                      total_of.data());
      EXPECT_TRUE(same_bits(got, expected)) << n << " wide, " << count << " rows";
      EXPECT_TRUE(same_bits(totals, expected_totals)) << n << " wide, " << count << " rows";
    }
  }
}

TEST(EntropyKernels, AddScaledIsTheScalarLoopBitForBit) {
  Rng rng(12);
  for (std::size_t n : {1u, 7u, 100u}) {
    const std::vector<double> x = draws(n, rng), start = draws(n, rng);
    std::vector<double> expected = start, got = start;
    for (std::size_t i = 0; i < n; ++i) {
      const double product = 0.37 * x[i];
      expected[i] = expected[i] + product;
    }
    add_scaled(got.data(), 0.37, x.data(), n);
    EXPECT_TRUE(same_bits(got, expected)) << n;
  }
}

TEST(EntropyKernels, DotIsTheSumOfProductsToRounding) {
  Rng rng(13);
  for (std::size_t n : {0u, 1u, 7u, 100u, 101u}) {
    const std::vector<double> x = draws(n, rng), y = draws(n, rng);
    long double expected = 0.0L;
    for (std::size_t i = 0; i < n; ++i)
      expected += static_cast<long double>(x[i]) * static_cast<long double>(y[i]);
    EXPECT_NEAR(dot(x.data(), y.data(), n), static_cast<double>(expected), 1e-13) << n;
  }
}

TEST(EntropyKernels, SumXLogXCountsTermsAtOrBelowZeroAsZero) {
  const std::vector<double> x = {0.5, 0.0, -1e-18, 0.25, 1.0, 0.125, 0.0625, 0.03125, 0.2};
  double expected = 0.0;
  for (double v : x)
    if (v > 0.0) expected += v * std::log(v);
  EXPECT_NEAR(sum_x_log_x(x.data(), x.size()), expected, 1e-14);
  EXPECT_EQ(sum_x_log_x(x.data(), 0), 0.0);
}

}  // namespace
}  // namespace echoplan::solvers
