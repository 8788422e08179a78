// What the physics hands to the sound: the effective mass of an impact (against the rigid-body
// formula), and impacts detected only when the object closes a gap to the table.
#include "sim/contact_recorder.h"

#include <gtest/gtest.h>

#include <cmath>

#include "scene_fixture.h"

namespace echoplan::sim {
namespace {

class ContactRecorderTest : public SceneAtInitialPose {
 protected:
  ContactRecorderTest() : SceneAtInitialPose("coffee_mug") {}
};

TEST_F(ContactRecorderTest, EffectiveMassUnderTheCentreOfMassIsTheWholeMass) {
  const mjtNum* com = d->xipos + 3 * scene.object_body;
  const mjtNum below[3] = {com[0], com[1], scene.table_top_z};
  EXPECT_NEAR(effective_mass(m, d, scene, below, Eigen::Vector3d::UnitZ()), object.total_mass(),
              1e-9);
}

TEST_F(ContactRecorderTest, EffectiveMassAtTheRimFollowsTheRigidBodyFormula) {
  // A vertical push at the rim, a lever arm R from the axis: 1/m_eff = 1/m + R^2 / I_horizontal.
  const mjtNum* com = d->xipos + 3 * scene.object_body;
  const mjtNum rim[3] = {com[0] + object.radius, com[1], scene.table_top_z};
  const double i_horizontal = object.inertia_diagonal()[1];
  const double expected =
      1.0 / (1.0 / object.total_mass() + object.radius * object.radius / i_horizontal);
  EXPECT_NEAR(effective_mass(m, d, scene, rim, Eigen::Vector3d::UnitZ()), expected,
              1e-6 * expected);
  EXPECT_LT(expected, object.total_mass());
}

TEST_F(ContactRecorderTest, ObjectRestingOrDroppedRecordsOneImpactOnlyWhenItFalls) {
  ContactTrace trace;
  ContactRecorder recorder(scene, object.radius, trace);
  auto run = [&](double seconds, double& time) {
    for (int k = 0; k < static_cast<int>(seconds / m->opt.timestep); ++k) {
      mj_step1(m, d);
      recorder.before_forces(m, d, time);
      for (int i = 0; i < kArmJoints; ++i) {
        d->ctrl[i] = kInitialArmConfiguration[i];
        d->qfrc_applied[i] = d->qfrc_bias[i];
      }
      mj_step2(m, d);
      recorder.after_forces(m, d);
      time += m->opt.timestep;
    }
  };
  double time = 0;
  run(0.3, time);  // resting: it presses on the table but closes no gap
  EXPECT_TRUE(trace.impacts.empty());
  EXPECT_GT(trace.normal_force.back(), 0.5 * object.total_mass() * 9.81);
  // Lift it 5 mm and let go: free fall for ~32 ms, hitting at sqrt(2 g h) = 0.31 m/s.
  d->qpos[scene.object_qpos + 2] += 0.005;
  mj_forward(m, d);
  run(0.3, time);
  ASSERT_EQ(trace.impacts.size(), 1u);
  EXPECT_NEAR(trace.impacts[0].normal_speed, std::sqrt(2 * 9.81 * 0.005), 0.05);
  EXPECT_NEAR(trace.impacts[0].time_s, 0.3 + std::sqrt(2 * 0.005 / 9.81), 0.01);
  EXPECT_FALSE(recorder.arm_on_table());
  EXPECT_EQ(trace.steps, static_cast<int>(trace.normal_force.size()));
}

}  // namespace
}  // namespace echoplan::sim
