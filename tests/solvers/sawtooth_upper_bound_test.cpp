// The sawtooth upper bound: interpolation between corners and points, pruning that keeps the bound.
#include "solvers/sawtooth_upper_bound.h"

#include <gtest/gtest.h>

namespace echoplan::solvers {
namespace {

TEST(SawtoothUpperBound, InterpolatesBetweenCornersAndPoints) {
  // Corners 10 and 20 (from one FIB vector); a point at the middle with value 5.
  SawtoothUpperBound bound({{10.0, 20.0}}, 100.0);
  EXPECT_DOUBLE_EQ(bound.value({0.5, 0.5}), 15.0);
  EXPECT_TRUE(bound.add({0.5, 0.5}, 5.0));
  EXPECT_DOUBLE_EQ(bound.value({0.5, 0.5}), 5.0);
  // At (0.75, 0.25): corners give 12.5; ratio min(0.75/0.5, 0.25/0.5) = 0.5; 12.5 + 0.5 * (5 - 15).
  EXPECT_DOUBLE_EQ(bound.value({0.75, 0.25}), 7.5);
  EXPECT_DOUBLE_EQ(bound.value({1.0, 0.0}), 10.0);
  // A point no better than the bound is not kept.
  EXPECT_FALSE(bound.add({0.75, 0.25}, 8.0));
  EXPECT_EQ(bound.num_points(), 1u);
  // A corner update lowers the corner and what is interpolated from it.
  EXPECT_TRUE(bound.add({1.0, 0.0}, 6.0));
  EXPECT_DOUBLE_EQ(bound.value({1.0, 0.0}), 6.0);
  // Corners now 6, 20: at (0.75, 0.25) 9.5 + 0.5 * (5 - 13) = 5.5.
  EXPECT_DOUBLE_EQ(bound.value({0.75, 0.25}), 5.5);
}

TEST(SawtoothUpperBound, PruneKeepsTheBoundAndDropsImpliedPoints) {
  SawtoothUpperBound bound({{10.0, 10.0}}, 100.0);
  ASSERT_TRUE(bound.add({0.5, 0.5}, 4.0));
  ASSERT_TRUE(bound.add({0.25, 0.75}, 5.0));  // the first point implies 7 here, so it is kept
  // Lower the middle so the second point is implied: at (0.25, 0.75) 10 + 0.5 * (0 - 10) = 5.
  ASSERT_TRUE(bound.add({0.5, 0.5}, 0.0));
  const double before = bound.value({0.3, 0.7});
  bound.prune();
  EXPECT_EQ(bound.num_points(), 1u);
  EXPECT_DOUBLE_EQ(bound.value({0.3, 0.7}), before);
}

}  // namespace
}  // namespace echoplan::solvers
