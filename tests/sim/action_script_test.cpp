#include "sim/action_script.h"

#include <gtest/gtest.h>

#include "sim/scene.h"

namespace echoplan::sim {
namespace {

ActionVariation nominal() {
  ActionVariation p;
  p.impact_speed = 0.1;
  p.push_speed = 0.05;
  p.grasp_height = 0.08;
  return p;
}

TEST(ActionScript, StrikeLiftsFiveCentimetresAndStopsOnContactBelowTheStart) {
  const Eigen::Vector3d at(0.4, 0.0, 0.1);
  const auto script =
      action_script(SoundAction::strike, nominal(), at, Eigen::Quaterniond::Identity(), {});
  ASSERT_EQ(script.size(), 8u);
  EXPECT_NEAR((script[1].to - at).z(), 0.05, 1e-12);  // the lift
  EXPECT_TRUE(script[3].stop_on_contact);             // the descent, and only it
  EXPECT_NEAR(script[3].to.z(), at.z() - kPressDepth, 1e-12);
  int stopping = 0;
  for (const Segment& s : script) stopping += s.stop_on_contact;
  EXPECT_EQ(stopping, 1);
  EXPECT_EQ(script.front().grasp_to, 1.0);  // the hand closes first and opens at the end
  EXPECT_EQ(script.back().grasp_from, 0.0);
}

TEST(ActionScript, SlidePushesFiveCentimetresAtTheDrawnSpeedWithTheArmsProfile) {
  const Eigen::Vector3d at(0.4, 0.0, 0.1);
  ArmConfig arm;
  const ActionVariation p = nominal();
  const auto script = action_script(SoundAction::slide, p, at, Eigen::Quaterniond::Identity(), arm);
  ASSERT_EQ(script.size(), 2u);
  const Segment& push = script[0];
  // 5 cm plus the 1 mm gap to the object, at the drawn mean speed.
  EXPECT_NEAR((push.to - push.from).x(), 0.051, 1e-12);
  EXPECT_NEAR(push.duration_s, 0.051 / p.push_speed, 1e-12);
  EXPECT_NEAR(push.ease_in_s, arm.push_accelerate_share * push.duration_s, 1e-12);
  EXPECT_NEAR(push.ease_out_s, arm.push_decelerate_share * push.duration_s, 1e-12);
  EXPECT_EQ(push.grasp_from + push.grasp_to, 0.0);  // a push, not a grasp
}

TEST(ActionScript, StrikeStartsAtTheGraspSlideBehindTheObject) {
  ActionVariation p = nominal();
  p.grasp_offset_x = 0.002;
  const Eigen::Vector3d base(0.5, 0.1, 0.7);
  const Eigen::Vector3d strike = action_start(SoundAction::strike, p, base, 0.04, 0.7);
  EXPECT_NEAR(strike.x(), 0.502, 1e-12);
  EXPECT_NEAR(strike.z(), 0.78, 1e-12);
  const Eigen::Vector3d slide = action_start(SoundAction::slide, p, base, 0.04, 0.7);
  // The pad's edge 1 mm from the object's wall.
  EXPECT_NEAR(base.x() - 0.04 - slide.x(), kPadRadius + 0.001, 1e-12);
}

}  // namespace
}  // namespace echoplan::sim
