// The arm's Cartesian motions: the trapezoidal speed profile of a segment, and the damped
// least-squares step that turns an end-effector pose into joint targets (checked against the
// arm's forward kinematics computed independently from Kinova's joint table).
#include "sim/cartesian_motion.h"

#include <gtest/gtest.h>

#include <array>
#include <memory>

#include "shipped_catalogue.h"
#include "sim/arm_kinematics.h"
#include "sim/scene.h"

namespace echoplan::sim {
namespace {

TEST(Segment, TrapezoidalProgressStartsAndEndsAtRestAndCruisesAtConstantSpeed) {
  Segment s{};
  s.duration_s = 1.0;
  s.ease_in_s = s.ease_out_s = 0.2;
  EXPECT_DOUBLE_EQ(s.progress(0.0), 0.0);
  EXPECT_NEAR(s.progress(1.0), 1.0, 1e-12);
  // Cruise speed: the whole path over the duration less half of each ramp (area of a trapezoid).
  const double cruise = 1.0 / (1.0 - 0.1 - 0.1);
  EXPECT_NEAR(s.progress(0.6) - s.progress(0.4), 0.2 * cruise, 1e-12);
  // Speed near the ends tends to zero (no jump in speed); the profile is symmetric.
  EXPECT_LT((s.progress(0.001) - s.progress(0.0)) / 0.001, 0.01 * cruise);
  EXPECT_NEAR(s.progress(0.3), 1.0 - s.progress(0.7), 1e-12);
  double previous = 0;
  for (int k = 1; k <= 100; ++k) {
    const double p = s.progress(k / 100.0);
    EXPECT_GE(p, previous);
    previous = p;
  }
}

// The slide's push accelerates for longer than it decelerates (ArmConfig's shares).
TEST(Segment, AsymmetricRampsReachCruiseWhereTheEaseInEnds) {
  Segment s{};
  s.duration_s = 2.0;
  s.ease_in_s = 0.8;
  s.ease_out_s = 0.4;
  const double cruise = 1.0 / (2.0 - 0.4 - 0.2);  // path shares per second at full speed
  EXPECT_NEAR(s.progress(0.8), 0.5 * cruise * 0.8, 1e-12);
  EXPECT_NEAR(s.progress(1.6), 0.5 * cruise * 0.8 + 0.8 * cruise, 1e-12);
  EXPECT_NEAR(s.progress(2.0), 1.0, 1e-12);
  // Speed (numerical) halfway up the ramp is half the cruise; the top is reached only at 0.8 s.
  EXPECT_NEAR((s.progress(0.401) - s.progress(0.399)) / 0.002, 0.5 * cruise, 1e-6);
  EXPECT_NEAR((s.progress(1.201) - s.progress(1.199)) / 0.002, cruise, 1e-9);
}

// Ramps that together outlast the segment shrink in proportion: the speed rises and falls as a
// triangle peaking where the ramps meet, and the whole path is still covered.
TEST(Segment, RampsLongerThanTheSegmentShrinkInProportion) {
  Segment s{};
  s.duration_s = 1.0;
  s.ease_in_s = 0.9;
  s.ease_out_s = 0.3;  // squeezed to 0.75 and 0.25
  const double top = 1.0 / (1.0 - 0.375 - 0.125);
  EXPECT_NEAR(s.progress(0.75), 0.5 * top * 0.75, 1e-12);
  EXPECT_NEAR(s.progress(1.0), 1.0, 1e-12);
  EXPECT_NEAR((s.progress(0.7501) - s.progress(0.7499)) / 0.0002, top, 1e-3);
}

TEST(Segment, WithoutEasingTheSpeedIsConstant) {
  Segment s{};
  s.duration_s = 2.0;
  EXPECT_DOUBLE_EQ(s.progress(0.5), 0.25);
  EXPECT_DOUBLE_EQ(s.progress(1.5), 0.75);
}

// The strike's descent eases in but not out (it stops on contact). The robot asks for the progress
// at duration * k / steps, which rounding can put past the end: 0.738954 * 369 / 369 is one ulp
// above 0.738954. That once divided by the zero ease-out and sent the joint targets to NaN; MuJoCo
// zeroed the servos and the arm fell onto the table, logged as a collision. It takes a descent that
// reaches its end without meeting the table (seen in a mug strike made after a slide).
TEST(Segment, TimesAtOrJustPastTheEndGiveTheWholePathWithoutEaseOut) {
  Segment s{};
  s.duration_s = 0.738954;
  s.ease_in_s = 0.1;
  const double past = s.duration_s * 369 / 369;
  ASSERT_GT(past, s.duration_s);  // the rounding the robot meets
  EXPECT_DOUBLE_EQ(s.progress(past), 1.0);
  EXPECT_DOUBLE_EQ(s.progress(s.duration_s), 1.0);
  EXPECT_DOUBLE_EQ(s.progress(s.duration_s + 1.0), 1.0);
  EXPECT_DOUBLE_EQ(s.progress(-1.0), 0.0);
  s.ease_in_s = 0;  // and without easing at either end
  EXPECT_DOUBLE_EQ(s.progress(past), 1.0);
}

TEST(DampedLeastSquares, ReachesANearbyPoseOfTheRealArm) {
  const Scene scene(shipped_catalogue().object("coffee_mug"), shipped_catalogue().table,
                    PhysicsConfig{});
  const mjModel* m = scene.model();
  auto kin = std::unique_ptr<mjData, void (*)(mjData*)>(mj_makeData(m), mj_deleteData);
  std::array<double, kArmJoints> q = kInitialArmConfiguration;
  const Eigen::Isometry3d start = end_effector_pose(q);
  // 4 cm forward and 3 cm up, the hand turned by 10 degrees about the vertical.
  const Eigen::Vector3d want = start.translation() + Eigen::Vector3d(0.04, 0.0, 0.03);
  const Eigen::Quaterniond want_rot =
      Eigen::Quaterniond(Eigen::AngleAxisd(0.17453, Eigen::Vector3d::UnitZ())) *
      Eigen::Quaterniond(start.rotation());
  for (int i = 0; i < 40; ++i)
    dls_step(m, kin.get(), scene.end_effector_site, q.data(), want, want_rot);
  const Eigen::Isometry3d reached = end_effector_pose(q);
  EXPECT_LT((reached.translation() - want).norm(), 1e-4);
  EXPECT_LT(Eigen::AngleAxisd(Eigen::Quaterniond(reached.rotation()) * want_rot.inverse()).angle(),
            1e-3);
  // site_position/site_orientation read the same pose from MuJoCo's kinematic copy.
  for (int i = 0; i < kArmJoints; ++i) kin->qpos[i] = q[i];
  mj_kinematics(m, kin.get());
  EXPECT_LT((site_position(kin.get(), scene.end_effector_site) - reached.translation()).norm(),
            1e-9);
  EXPECT_LT(Eigen::AngleAxisd(site_orientation(kin.get(), scene.end_effector_site) *
                              Eigen::Quaterniond(reached.rotation()).inverse())
                .angle(),
            1e-9);
}

}  // namespace
}  // namespace echoplan::sim
