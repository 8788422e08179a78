#include "sim/arm_kinematics.h"

#include <gtest/gtest.h>

#include "shipped_catalogue.h"
#include "sim/catalogue.h"
#include "sim/scene.h"

namespace echoplan::sim {
namespace {

TEST(ArmKinematics, MujocoModelAgreesWithTheJointTable) {
  // Two independent computations of the same chain: Eigen from the table, MuJoCo from the generated
  // MJCF. Several configurations, including the initial one; agreement to 1e-9 m (double rounding).
  const Catalogue& c = shipped_catalogue();
  Scene scene(c.object("coffee_mug"), c.table, PhysicsConfig{});
  const mjModel* m = scene.model();
  mjData* d = scene.data();
  std::vector<std::array<double, 7>> configurations{
      kInitialArmConfiguration, {0, 0, 0, 0, 0, 0, 0}, {0.3, -1.0, 0.5, 1.2, -0.7, 0.9, 2.0}};
  for (const auto& q : configurations) {
    for (int i = 0; i < 7; ++i) d->qpos[i] = q[i];
    mj_kinematics(m, d);
    const Eigen::Isometry3d pose = end_effector_pose(q);
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(d->site_xpos[3 * scene.end_effector_site + k], pose.translation()[k], 1e-9);
    for (int k = 0; k < 9; ++k)
      EXPECT_NEAR(d->site_xmat[9 * scene.end_effector_site + k], pose.rotation()(k / 3, k % 3),
                  1e-9);
  }
}

TEST(ArmKinematics, InitialConfigurationPointsTheHandDown) {
  const Eigen::Isometry3d pose = end_effector_pose(kInitialArmConfiguration);
  // The end effector's z axis (its approach direction) is within 25 degrees of straight down.
  EXPECT_LT(pose.rotation().col(2).z(), -0.9);
}

TEST(ArmKinematics, JointLimitsAreInTheModel) {
  const Catalogue& c = shipped_catalogue();
  Scene scene(c.object("coffee_mug"), c.table, PhysicsConfig{});
  const mjModel* m = scene.model();
  const double limits[7] = {0, 2.35, 0, 2.65, 0, 2.25, 0};
  for (int j = 0; j < 7; ++j) {
    EXPECT_EQ(m->jnt_limited[j] != 0, limits[j] > 0) << j;
    if (limits[j] > 0) {
      EXPECT_DOUBLE_EQ(m->jnt_range[2 * j], -limits[j]);
      EXPECT_DOUBLE_EQ(m->jnt_range[2 * j + 1], limits[j]);
    }
  }
}

}  // namespace
}  // namespace echoplan::sim
