#include "sim/scene.h"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <cstring>
#include <mutex>
#include <stdexcept>

#include "sim/arm_kinematics.h"

namespace echoplan::sim {

namespace {

constexpr double kTableHalfSize =
    0.3;  // m, drawn size of the table; it collides as an infinite plane
constexpr double kUpperLinkRadius = 0.035;  // m, capsules approximating the shoulder and upper arm
constexpr double kLowerLinkRadius = 0.03;   // m, forearm and wrist
constexpr double kHandRadius = 0.03;        // m, the hand and closed fingers
constexpr double kServoStiffness = 1000;    // N m / rad, joint position servos
constexpr double kJointDamping = 20;        // N m s / rad, about critical with the armature below
constexpr double kArmature = 0.1;           // kg m^2, reflected rotor inertia of the geared joints
constexpr int kSolverIterations = 20;  // constraint solver; converges in a few for this small scene
constexpr double kArmFriction = 1.0;   // MuJoCo's default sliding friction: the arm's capsules
constexpr double kPadFriction = 0.2;   // the finger pads' and the object's own sliding friction
constexpr double kTorsionalFriction = 0.005;  // every geom's
constexpr double kRollingFriction = 0.0001;   // every geom's
// s, MuJoCo solref time constant of the object-table contact: stiff enough that the object does
// not bounce on its resting contact; softer ones were measured and not kept (docs/simulator.md,
// "The mug strike: second hit, tilted landing, low frequencies").
constexpr double kObjectContactTime = 0.01;

// The arm as nested bodies, one per joint, each with a capsule from its origin to the next joint.
std::string arm_mjcf(PadContact pad) {
  std::string xml;
  std::string closing;
  for (std::size_t i = 0; i < kJaco2Joints.size(); ++i) {
    const auto& j = kJaco2Joints[i];
    const bool last = i + 1 == kJaco2Joints.size();
    xml += fmt::format(R"(<body name="link{0}" pos="{1} {2} {3}" euler="{4} {5} {6}">)", i + 1,
                       j.xyz[0], j.xyz[1], j.xyz[2], j.rpy[0], j.rpy[1], j.rpy[2]);
    if (j.limit > 0)
      xml += fmt::format(R"(<joint name="joint{}" limited="true" range="{} {}"/>)", i + 1, -j.limit,
                         j.limit);
    else
      xml += fmt::format(R"(<joint name="joint{}"/>)", i + 1);
    if (!last) {
      const auto& next = kJaco2Joints[i + 1];
      // Link 1 is the column the arm is mounted on beside the table: it never collides.
      const int contype = i == 0 ? 0 : kContactArm, conaffinity = i == 0 ? 0 : kContactTable;
      xml += fmt::format(
          R"(<geom name="link{}" type="capsule" fromto="0 0 0 {} {} {}" size="{}" mass="{}" contype="{}" conaffinity="{}"/>)",
          i + 1, next.xyz[0], next.xyz[1], next.xyz[2], i < 3 ? kUpperLinkRadius : kLowerLinkRadius,
          j.link_mass, contype, conaffinity);
    } else {
      // The hand: a capsule down to just above the fingertips, the pad at the end effector.
      const double tip = kJaco2EndEffector.xyz[2];
      xml += fmt::format(
          R"(<geom name="hand" type="capsule" fromto="0 0 0 0 0 {}" size="{}" mass="{}" contype="{}" conaffinity="{}"/>)",
          tip + kHandRadius, kHandRadius, j.link_mass, kContactArm, kContactTable);
      // The pad: the closed fingers side by side, a capsule across the push direction (world y in
      // the initial configuration's hand orientation), so a pushed round object stays in front of
      // it.
      const Eigen::Matrix3d site_rotation = end_effector_pose(kInitialArmConfiguration).rotation();
      const Eigen::Matrix3d site_in_link =
          Eigen::AngleAxisd(kJaco2EndEffector.rpy[0], Eigen::Vector3d::UnitX()).toRotationMatrix();
      const Eigen::Vector3d across =
          kPadHalfWidth * (site_in_link * site_rotation.transpose() * Eigen::Vector3d::UnitY());
      xml += fmt::format(
          R"(<geom name="pad" type="capsule" fromto="{} {} {} {} {} {}" size="{}" mass="0.01" contype="{}" conaffinity="{}" friction="{} {} {}"/>)",
          -across.x(), -across.y(), tip - across.z(), across.x(), across.y(), tip + across.z(),
          kPadRadius, kContactArm,
          pad == PadContact::pushes_object ? (kContactTable | kContactObject) : kContactTable,
          kPadFriction, kTorsionalFriction, kRollingFriction);
      xml +=
          fmt::format(R"(<site name="end_effector" pos="0 0 {}" euler="{} {} {}"/>)", tip,
                      kJaco2EndEffector.rpy[0], kJaco2EndEffector.rpy[1], kJaco2EndEffector.rpy[2]);
    }
    closing += "</body>";
  }
  return xml + closing;
}

// The geom pairs that can touch, as MJCF <pair>s: the scene is simulated with collision=
// "predefined", so MuJoCo tests these and nothing else. They are the pairs the contype/conaffinity
// bits allow (the object-table pair, with its own friction and contact time, comes first in the
// scene), listed so that MuJoCo skips its broad phase (a bounding-box sweep with an eigen-
// decomposition and a sort at every step, ~8% of a recording's cost): every arm geom but the
// column with the table, and the pad with the object when it pushes. Each pair's contact
// parameters are those MuJoCo would mix from the two geoms for a dynamic contact (the larger
// friction coefficients, condim 3, default solref and solimp), so the contacts are the same.
std::string arm_contact_pairs(PadContact pad, double table_friction) {
  auto pair = [](const std::string& a, const std::string& b, double friction) {
    return fmt::format(R"(<pair geom1="{}" geom2="{}" condim="3" friction="{} {} {} {} {}"/>)", a,
                       b, friction, friction, kTorsionalFriction, kRollingFriction,
                       kRollingFriction);
  };
  std::string xml;
  for (std::size_t i = 1; i + 1 < kJaco2Joints.size(); ++i)
    xml += pair("table", fmt::format("link{}", i + 1), std::max(table_friction, kArmFriction));
  xml += pair("table", "hand", std::max(table_friction, kArmFriction));
  xml += pair("table", "pad", std::max(table_friction, kPadFriction));
  if (pad == PadContact::pushes_object) xml += pair("pad", "object", kPadFriction);
  return xml + "\n";
}

}  // namespace

std::string scene_mjcf(const ObjectSpec& object, const TableSpec& table,
                       const PhysicsConfig& physics, PadContact pad) {
  const Eigen::Vector3d ee = end_effector_pose(kInitialArmConfiguration).translation();
  const double table_top = ee.z() - kNominalGraspHeight;
  const double object_x = ee.x() + kObjectOffsetX, object_y = ee.y();
  const auto com = object.centre_of_mass();
  const auto inertia = object.inertia_diagonal();
  const double mu = object.friction;

  // The scene. The object-table contact is critically damped (solref's damping ratio 1), so the
  // object does not bounce on the contact's spring: real impacts are over within ~1 ms, and their
  // sound is the analytic Hertz pulse (contact_trace.h). Its 10 ms time constant is five steps at 2
  // ms, three at the slide's 3 ms (MuJoCo needs at least two). The object collides with the table
  // only through the explicit pair, which sets their friction.
  std::string xml = fmt::format(
      R"(<mujoco model="echoplan_scene">
<compiler angle="radian" eulerseq="XYZ"/>
<option timestep="{timestep}" integrator="Euler" cone="pyramidal" iterations="{iterations}" tolerance="1e-6" collision="predefined"/>
<size nconmax="100" njmax="400"/>
<default><joint damping="{damping}" armature="{armature}"/></default>
<worldbody>
<geom name="table" type="plane" pos="{ox} {oy} {top}" size="{half} {half} 0.01" contype="{ctable}" conaffinity="{cany}" friction="{tmu} 0.005 0.0001"/>
<body name="arm_base">{arm}</body>
<body name="object" pos="{ox} {oy} {top}">
<freejoint name="object_free"/>
<inertial pos="{cx} {cy} {cz}" mass="{mass}" diaginertia="{ix} {iy} {iz}"/>
<geom name="object" type="cylinder" pos="0 0 {hh}" size="{radius} {hh}" contype="{cobject}" conaffinity="{ctable}" friction="0.2 0.005 0.0001"/>
</body>
</worldbody>
<contact>
<exclude body1="world" body2="object"/>
<pair geom1="table" geom2="object" condim="3" friction="{mu} {mu} 0.005 0.0001 0.0001" solref="{contact_time} 1"/>
{arm_pairs}</contact>
<actuator>)",
      fmt::arg("timestep",
               pad == PadContact::pushes_object ? physics.slide_timestep_s : physics.timestep_s),
      fmt::arg("iterations", kSolverIterations), fmt::arg("contact_time", kObjectContactTime),
      fmt::arg("damping", kJointDamping), fmt::arg("armature", kArmature), fmt::arg("ox", object_x),
      fmt::arg("oy", object_y), fmt::arg("half", kTableHalfSize), fmt::arg("ctable", kContactTable),
      fmt::arg("cany", kContactTable | kContactArm), fmt::arg("tmu", table.friction),
      fmt::arg("arm", arm_mjcf(pad)), fmt::arg("arm_pairs", arm_contact_pairs(pad, table.friction)),
      fmt::arg("top", table_top), fmt::arg("cx", com[0]), fmt::arg("cy", com[1]),
      fmt::arg("cz", com[2]), fmt::arg("mass", object.total_mass()), fmt::arg("ix", inertia[0]),
      fmt::arg("iy", inertia[1]), fmt::arg("iz", inertia[2]), fmt::arg("hh", object.height / 2),
      fmt::arg("radius", object.radius), fmt::arg("cobject", kContactObject), fmt::arg("mu", mu));
  for (int i = 1; i <= kArmJoints; ++i)
    xml +=
        fmt::format(R"(<position name="servo{0}" joint="joint{0}" kp="{1}"/>)", i, kServoStiffness);
  xml += "</actuator>\n</mujoco>\n";
  return xml;
}

namespace {

// MuJoCo's warnings (a NaN in the controls, a full contact buffer) otherwise go to stdout and to
// MUJOCO_LOG.TXT in the working directory, where nobody looks and a run's output folder does not
// hold them: send them to the program's log (stderr) like every other warning.
void route_mujoco_warnings_to_the_log() {
  static std::once_flag once;
  std::call_once(once, [] {
    mju_user_warning = [](const char* message) { spdlog::warn("MuJoCo: {}", message); };
  });
}

// MuJoCo 2.2 compiles MJCF from files only: hand it the text through a virtual file system.
mjModel* compile(const std::string& xml) {
  route_mujoco_warnings_to_the_log();
  auto vfs = std::make_unique<mjVFS>();
  mj_defaultVFS(vfs.get());
  const char* name = "echoplan_scene.xml";
  if (mj_makeEmptyFileVFS(vfs.get(), name, static_cast<int>(xml.size())) != 0)
    throw std::runtime_error("MuJoCo: cannot create the scene's virtual file");
  std::memcpy(vfs->filedata[mj_findFileVFS(vfs.get(), name)], xml.data(), xml.size());
  char error[1024] = "";
  mjModel* m = mj_loadXML(name, vfs.get(), error, sizeof error);
  mj_deleteVFS(vfs.get());
  if (!m) throw std::runtime_error(std::string("MuJoCo rejected the generated scene: ") + error);
  return m;
}

// Do two models allocate mjData alike (so one mjData can be stepped with either)? Their own
// buffers differ: the pushing variant has one more contact pair.
bool same_data_layout(const mjModel* a, const mjModel* b) {
  return a->nq == b->nq && a->nv == b->nv && a->nu == b->nu && a->na == b->na &&
         a->nbody == b->nbody && a->njnt == b->njnt && a->ngeom == b->ngeom &&
         a->nsite == b->nsite && a->neq == b->neq && a->nmocap == b->nmocap &&
         a->nsensordata == b->nsensordata && a->nuserdata == b->nuserdata &&
         a->nconmax == b->nconmax && a->njmax == b->njmax && a->nstack == b->nstack &&
         a->nD == b->nD && a->nM == b->nM && a->nemax == b->nemax && a->ntendon == b->ntendon &&
         a->nwrap == b->nwrap && a->ncam == b->ncam && a->nlight == b->nlight;
}

}  // namespace

Scene::Scene(const ObjectSpec& object, const TableSpec& table, const PhysicsConfig& physics) {
  push_model_.reset(compile(scene_mjcf(object, table, physics, PadContact::pushes_object)));
  clear_model_.reset(compile(scene_mjcf(object, table, physics, PadContact::clear_of_object)));
  if (!same_data_layout(push_model_.get(), clear_model_.get()))
    throw std::runtime_error("the two scene variants differ in size; one mjData cannot serve both");
  data_.reset(mj_makeData(push_model_.get()));
  scratch_.reset(mj_makeData(push_model_.get()));

  const mjModel* m = push_model_.get();
  end_effector_site = mj_name2id(m, mjOBJ_SITE, "end_effector");
  object_body = mj_name2id(m, mjOBJ_BODY, "object");
  object_geom = mj_name2id(m, mjOBJ_GEOM, "object");
  table_geom = mj_name2id(m, mjOBJ_GEOM, "table");
  pad_geom = mj_name2id(m, mjOBJ_GEOM, "pad");
  hand_body = mj_name2id(m, mjOBJ_BODY, "link7");
  const int free_joint = mj_name2id(m, mjOBJ_JOINT, "object_free");
  object_qpos = m->jnt_qposadr[free_joint];
  object_dof = m->jnt_dofadr[free_joint];
  const Eigen::Vector3d ee = end_effector_pose(kInitialArmConfiguration).translation();
  table_top_z = ee.z() - kNominalGraspHeight;
  initial_end_effector_ = {ee.x(), ee.y(), ee.z()};
}

bool Scene::is_arm_geom(int g) const {
  const mjModel* m = push_model_.get();
  const int body = m->geom_bodyid[g];
  return body != 0 && body != object_body;
}

}  // namespace echoplan::sim
