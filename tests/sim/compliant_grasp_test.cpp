// The compliant grasp: it carries the object's weight, pulls it back to the held pose like a
// critically damped spring, and pushes the hand with the equal and opposite force (momentum is
// conserved; nothing is written to the model).
#include "sim/compliant_grasp.h"

#include <gtest/gtest.h>

#include "scene_fixture.h"

namespace echoplan::sim {
namespace {

class CompliantGraspTest : public SceneAtInitialPose {
 protected:
  CompliantGraspTest() : SceneAtInitialPose("plastic_cup") {}
  Eigen::Vector3d force_on(int body) const { return Eigen::Vector3d(d->xfrc_applied + 6 * body); }
};

TEST_F(CompliantGraspTest, HeldInPlaceItCarriesTheWeightInProportionToItsStrength) {
  CompliantGrasp grasp(scene);
  grasp.close(d);
  const double weight = object.total_mass() * 9.81;
  grasp.apply(m, d, 1.0);
  EXPECT_NEAR(force_on(scene.object_body).z(), weight, 1e-6 * weight);
  EXPECT_NEAR(force_on(scene.object_body).head<2>().norm(), 0.0, 1e-9);
  EXPECT_NEAR(Eigen::Vector3d(d->xfrc_applied + 6 * scene.object_body + 3).norm(), 0.0, 1e-9);
  EXPECT_LT((force_on(scene.hand_body) + force_on(scene.object_body)).norm(), 1e-12);
  grasp.apply(m, d, 0.5);
  EXPECT_NEAR(force_on(scene.object_body).z(), 0.5 * weight, 1e-6 * weight);
  grasp.apply(m, d, 0.0);  // open: no force on either
  EXPECT_EQ(force_on(scene.object_body).norm(), 0.0);
  EXPECT_EQ(force_on(scene.hand_body).norm(), 0.0);
}

TEST_F(CompliantGraspTest, DisplacedObjectIsPulledBackAsASpring) {
  CompliantGrasp grasp(scene);
  grasp.close(d);
  d->qpos[scene.object_qpos + 0] += 0.002;  // 2 mm off the held pose along x, at rest
  mj_forward(m, d);
  grasp.apply(m, d, 1.0);
  // F = m omega^2 x with the grasp's omega of 150 rad/s, towards the held pose.
  const double expected = object.total_mass() * 150.0 * 150.0 * 0.002;
  EXPECT_NEAR(force_on(scene.object_body).x(), -expected, 1e-6 * expected);
  EXPECT_LT((force_on(scene.hand_body) + force_on(scene.object_body)).norm(), 1e-9);
}

}  // namespace
}  // namespace echoplan::sim
