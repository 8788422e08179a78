// The 95% CI helper against Student's t table values (independent references) and a hand-worked
// sample.
#include "common/statistics.h"

#include <gtest/gtest.h>

#include <cmath>

namespace echoplan {
namespace {

TEST(Statistics, StudentQuantileMatchesTables) {
  EXPECT_NEAR(student_t_975(1), 12.7062, 1e-4);
  EXPECT_NEAR(student_t_975(2), 4.3027, 1e-4);
  EXPECT_NEAR(student_t_975(10), 2.2281, 1e-4);
  EXPECT_NEAR(student_t_975(30), 2.0423, 1e-4);
  // Beyond the table, the expansion: t(0.975, 40) = 2.0211, 60: 2.0003, 120: 1.9799.
  EXPECT_NEAR(student_t_975(40), 2.0211, 1e-4);
  EXPECT_NEAR(student_t_975(60), 2.0003, 1e-4);
  EXPECT_NEAR(student_t_975(120), 1.9799, 1e-4);
  EXPECT_NEAR(student_t_975(100000), 1.95998, 1e-4);
}

TEST(Statistics, MeanIntervalOfASmallSample) {
  // 1, 2, 3, 4: mean 2.5, sd sqrt(5/3), half-width t(0.975, 3) sd / 2 = 3.1824 * 1.29099 / 2.
  const MeanInterval m = mean_ci95({1.0, 2.0, 3.0, 4.0});
  EXPECT_EQ(m.n, 4);
  EXPECT_DOUBLE_EQ(m.mean, 2.5);
  EXPECT_NEAR(m.sd, std::sqrt(5.0 / 3.0), 1e-12);
  EXPECT_NEAR(m.half_width, 3.182446305 * std::sqrt(5.0 / 3.0) / 2.0, 1e-9);
  // One value: a mean but no interval.
  EXPECT_EQ(mean_ci95({7.0}).half_width, 0.0);
  EXPECT_EQ(mean_ci95({}).n, 0);
}

}  // namespace
}  // namespace echoplan
