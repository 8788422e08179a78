// The progress line: bar, count and time left.
#include "experiment/progress_bar.h"

#include <gtest/gtest.h>

namespace echoplan::experiment {
namespace {

TEST(ProgressBar, ShowsDoneTotalAndTimeLeft) {
  EXPECT_EQ(ProgressBar::render("trials", 0, 10, 0.0),
            "[------------------------------] 0/10 trials, estimating");
  // 4 left at 30 s each: 2 minutes.
  EXPECT_EQ(ProgressBar::render("trials", 6, 10, 30.0),
            "[##################------------] 6/10 trials, 2:00 left");
  EXPECT_EQ(ProgressBar::render("clips", 80, 80, 0.5),
            "[##############################] 80/80 clips, 0:00 left");
}

}  // namespace
}  // namespace echoplan::experiment
