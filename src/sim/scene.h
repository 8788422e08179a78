// The MuJoCo scene: a table, the Kinova Jaco2 7-DOF arm (j2s7s300 kinematics) and one object.
//
// The MJCF model is generated from the catalogue entry, compiled once per object and owned here
// together with its mjData. MuJoCo's own split applies: the models never change after compiling
// (the robot only ever sees them as const); mjData holds the state, including the grasp, which the
// robot applies as forces through mjData::xfrc_applied.
//
// MuJoCo 2.2 (Debian's) keeps contact filters in mjModel, and the fingertip pad must touch the
// object when it pushes but not when the hand closes around the object. So the scene is compiled
// twice, the two variants differing only in the pad's conaffinity; both have the same sizes, so the
// one mjData (the trial's state) is stepped with whichever variant the current action needs.
#pragma once

#include <mujoco/mujoco.h>

#include <array>
#include <memory>
#include <string>

#include "sim/catalogue.h"
#include "sim/sim_config.h"

namespace echoplan::sim {

inline constexpr int kArmJoints = 7;

// The original system's initial joint configuration (rad), with the object 0.1 m along x from the
// end effector.
inline constexpr std::array<double, kArmJoints> kInitialArmConfiguration{
    -2.89527, 1.45058, -0.18396, 2.07696, -0.310356, 0.630897, -1.54233};
inline constexpr double kPadRadius = 0.012;  // m, the fingertip pad that pushes in a slide
inline constexpr double kPadHalfWidth =
    0.02;  // m, half the span of the closed fingers across the push
inline constexpr double kObjectOffsetX = 0.1;  // m, object from end effector at the start
// m, end effector above the table at the start: the arm's forearm then clears the table by ~2 cm.
inline constexpr double kNominalGraspHeight = 0.085;

// Contact filter bits (MuJoCo contype/conaffinity). The arm touches the table only; the fingertip
// pad touches the table and, when pushing, the object; the object touches the table through an
// explicit contact pair.
inline constexpr int kContactTable = 1;
inline constexpr int kContactObject = 2;
inline constexpr int kContactArm = 4;

// Which compiled variant of the scene: does the fingertip pad collide with the object?
enum class PadContact { pushes_object, clear_of_object };

// The MJCF text of the scene for `object` on `table` (for inspection and tests). The variant whose
// pad pushes is the slide's and steps at `physics.slide_timestep_s`; the other at `timestep_s`.
std::string scene_mjcf(const ObjectSpec& object, const TableSpec& table,
                       const PhysicsConfig& physics, PadContact pad = PadContact::pushes_object);

class Scene {
 public:
  // Compiles the scene. Throws std::runtime_error if MuJoCo rejects the model (a bug, not user
  // input: catalogue values are validated on loading).
  Scene(const ObjectSpec& object, const TableSpec& table, const PhysicsConfig& physics);

  // The model variant for `pad` (default: the one whose pad pushes). Never written after compiling.
  const mjModel* model(PadContact pad = PadContact::pushes_object) const {
    return pad == PadContact::pushes_object ? push_model_.get() : clear_model_.get();
  }
  mjData* data() const { return data_.get(); }
  // A second mjData for kinematic look-ahead (the inverse kinematics' trial poses), never the
  // trial's state: kept here so an action does not allocate one (mj_makeData zeroes megabytes).
  mjData* scratch() const { return scratch_.get(); }

  // Ids into the model.
  int end_effector_site = -1;
  int object_body = -1;
  int object_geom = -1;
  int table_geom = -1;
  int pad_geom = -1;
  int hand_body = -1;
  int object_qpos = -1;    // address of the object's free joint in qpos (3 position + 4 quaternion)
  int object_dof = -1;     // address of its 6 velocities in qvel
  double table_top_z = 0;  // m, world height of the table surface

  // World position of the end effector in the initial configuration.
  std::array<double, 3> initial_end_effector() const { return initial_end_effector_; }

  // Is geom `g` part of the arm (links, hand, pad)?
  bool is_arm_geom(int g) const;

 private:
  struct ModelDeleter {
    void operator()(mjModel* m) const { mj_deleteModel(m); }
  };
  struct DataDeleter {
    void operator()(mjData* d) const { mj_deleteData(d); }
  };
  std::unique_ptr<mjModel, ModelDeleter> push_model_, clear_model_;
  std::unique_ptr<mjData, DataDeleter> data_, scratch_;
  std::array<double, 3> initial_end_effector_{};
};

}  // namespace echoplan::sim
