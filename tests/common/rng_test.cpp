#include "common/rng.h"

#include <gtest/gtest.h>

#include <set>

namespace echoplan {
namespace {

TEST(DeriveSeed, IsDeterministicAndSeparatesStreams) {
  EXPECT_EQ(derive_seed(7, {1, 2}), derive_seed(7, {1, 2}));
  std::set<std::uint64_t> seen;
  for (std::uint64_t base : {0, 1, 7})
    for (std::uint64_t a = 0; a < 20; ++a)
      for (std::uint64_t b = 0; b < 20; ++b) seen.insert(derive_seed(base, {a, b}));
  EXPECT_EQ(seen.size(), 3u * 20u * 20u);
  EXPECT_NE(derive_seed(7, {1, 2}), derive_seed(7, {2, 1}));
}

TEST(Uniform01, StaysInUnitIntervalWithMeanNearHalf) {
  Rng rng(42);
  double sum = 0;
  const int n = 100000;
  for (int i = 0; i < n; ++i) {
    double u = uniform01(rng);
    ASSERT_GE(u, 0.0);
    ASSERT_LT(u, 1.0);
    sum += u;
  }
  // Standard error of the mean of U(0,1) over 1e5 draws is 0.0009; 5 sigma.
  EXPECT_NEAR(sum / n, 0.5, 0.0046);
}

}  // namespace
}  // namespace echoplan
