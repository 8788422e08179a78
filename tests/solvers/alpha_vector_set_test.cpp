// Alpha-vector sets: pointwise-dominated plans are dropped, the best plan is found.
#include "solvers/alpha_vector_set.h"

#include <gtest/gtest.h>

namespace echoplan::solvers {
namespace {

TEST(AlphaVectorSet, PrunesPointwiseDominatedVectors) {
  AlphaVectorSet set;
  EXPECT_TRUE(set.add({0, {1.0, 1.0}}));
  EXPECT_FALSE(set.add({1, {0.5, 1.0}}));  // dominated by the first
  EXPECT_TRUE(set.add({2, {0.0, 3.0}}));   // better at the right corner
  EXPECT_EQ(set.size(), 2u);
  EXPECT_TRUE(set.add({3, {2.0, 1.0}}));  // dominates the first, which goes
  ASSERT_EQ(set.size(), 2u);
  EXPECT_EQ(set.best_action({1.0, 0.0}), 3);
  EXPECT_EQ(set.best_action({0.0, 1.0}), 2);
  EXPECT_DOUBLE_EQ(set.value({0.5, 0.5}), 1.5);
}

}  // namespace
}  // namespace echoplan::solvers
