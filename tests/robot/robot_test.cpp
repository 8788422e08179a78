// The names of the robot's action outcomes, as the loop's logs (loop_steps.csv, loop_steps.jsonl)
// and its printed steps spell them.
#include "robot/robot.h"

#include <gtest/gtest.h>

#include <string>

namespace echoplan::robot {
namespace {

TEST(Robot, EachActionStatusHasItsLogName) {
  EXPECT_EQ(std::string(to_string(ActionStatus::done)), "done");
  EXPECT_EQ(std::string(to_string(ActionStatus::collision)), "collision");
  EXPECT_EQ(std::string(to_string(ActionStatus::failed)), "failed");
}

}  // namespace
}  // namespace echoplan::robot
