// Test fixture shared by the sim tests that work on the compiled scene directly: one shipped object
// on the shipped table, the arm in the original system's initial configuration and the object at
// rest at its nominal place (positions and velocities computed by mj_forward).
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "shipped_catalogue.h"
#include "sim/scene.h"

namespace echoplan::sim {

class SceneAtInitialPose : public ::testing::Test {
 protected:
  explicit SceneAtInitialPose(const std::string& object_name)
      : object(shipped_catalogue().object(object_name)),
        scene(object, shipped_catalogue().table, PhysicsConfig{}),
        m(scene.model()),
        d(scene.data()) {
    mj_resetData(m, d);
    for (int i = 0; i < kArmJoints; ++i) d->qpos[i] = kInitialArmConfiguration[i];
    mj_forward(m, d);
  }

  const ObjectSpec& object;
  Scene scene;
  const mjModel* m;
  mjData* d;
};

}  // namespace echoplan::sim
