// The compiled MuJoCo scene: the object's rigid body is the catalogue's, the two model variants
// differ only where they must (the pad's contact with the object), and the arm and object stand
// where the original system's initial configuration puts them.
#include "sim/scene.h"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <spdlog/sinks/ringbuffer_sink.h>
#include <spdlog/spdlog.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>

#include "shipped_catalogue.h"
#include "sim/arm_kinematics.h"

namespace echoplan::sim {
namespace {

TEST(Scene, ObjectBodyCarriesTheCataloguesMassCentreAndInertia) {
  // The weighted mug: its added mass moves the centre of mass down and raises the total mass, and
  // the compiled body must say so (the effective mass of every impact comes from it).
  const ObjectSpec& mug = shipped_catalogue().object("coffee_mug_weighted");
  const Scene scene(mug, shipped_catalogue().table, PhysicsConfig{});
  const mjModel* m = scene.model();
  EXPECT_NEAR(m->body_mass[scene.object_body], mug.total_mass(), 1e-9);
  const auto com = mug.centre_of_mass();
  const auto inertia = mug.inertia_diagonal();
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(m->body_ipos[3 * scene.object_body + k], com[k], 1e-9);
    // MuJoCo may reorder the principal axes; the mug is axisymmetric about z, so x and y agree.
    EXPECT_NEAR(m->body_inertia[3 * scene.object_body + k], inertia[k], 1e-9 * inertia[2]);
  }
  // The collision cylinder spans the object: radius and half height as catalogued.
  EXPECT_NEAR(m->geom_size[3 * scene.object_geom], mug.radius, 1e-12);
  EXPECT_NEAR(m->geom_size[3 * scene.object_geom + 1], mug.height / 2, 1e-12);
}

TEST(Scene, VariantsDifferOnlyInWhetherThePadTouchesTheObject) {
  const Scene scene(shipped_catalogue().object("plastic_cup"), shipped_catalogue().table,
                    PhysicsConfig{});
  const mjModel* push = scene.model(PadContact::pushes_object);
  const mjModel* clear = scene.model(PadContact::clear_of_object);
  ASSERT_EQ(push->ngeom, clear->ngeom);
  ASSERT_EQ(push->nq, clear->nq);
  for (int g = 0; g < push->ngeom; ++g) {
    EXPECT_EQ(push->geom_contype[g], clear->geom_contype[g]) << g;
    if (g == scene.pad_geom) continue;
    EXPECT_EQ(push->geom_conaffinity[g], clear->geom_conaffinity[g]) << g;
  }
  // MuJoCo's filter: two geoms collide if (contype1 & conaffinity2) || (contype2 & conaffinity1).
  auto collide = [&](const mjModel* m, int a, int b) {
    return (m->geom_contype[a] & m->geom_conaffinity[b]) ||
           (m->geom_contype[b] & m->geom_conaffinity[a]);
  };
  EXPECT_TRUE(collide(push, scene.pad_geom, scene.object_geom));
  EXPECT_FALSE(collide(clear, scene.pad_geom, scene.object_geom));
  EXPECT_TRUE(collide(clear, scene.pad_geom, scene.table_geom));
}

TEST(Scene, InitialPoseHasTheObjectAheadOfTheHandOnTheTable) {
  const ObjectSpec& can = shipped_catalogue().object("pringles_can");
  const Scene scene(can, shipped_catalogue().table, PhysicsConfig{});
  const mjModel* m = scene.model();
  mjData* d = scene.data();
  mj_resetData(m, d);
  for (int i = 0; i < kArmJoints; ++i) d->qpos[i] = kInitialArmConfiguration[i];
  mj_forward(m, d);
  const Eigen::Vector3d ee = end_effector_pose(kInitialArmConfiguration).translation();
  for (int k = 0; k < 3; ++k)
    EXPECT_NEAR(d->site_xpos[3 * scene.end_effector_site + k], ee[k], 1e-9);
  EXPECT_NEAR(scene.table_top_z, ee.z() - kNominalGraspHeight, 1e-12);
  // The object's base centre: kObjectOffsetX ahead of the end effector along x, on the table top.
  EXPECT_NEAR(d->xpos[3 * scene.object_body], ee.x() + kObjectOffsetX, 1e-9);
  EXPECT_NEAR(d->xpos[3 * scene.object_body + 1], ee.y(), 1e-9);
  EXPECT_NEAR(d->xpos[3 * scene.object_body + 2], scene.table_top_z, 1e-9);
  // Nothing but the object rests on the table at the start: the arm is clear of it.
  for (int i = 0; i < d->ncon; ++i) {
    EXPECT_FALSE(scene.is_arm_geom(d->contact[i].geom1)) << i;
    EXPECT_FALSE(scene.is_arm_geom(d->contact[i].geom2)) << i;
  }
}

TEST(Scene, ArmGeomsAreTheLinksHandAndPadNotTableOrObject) {
  const Scene scene(shipped_catalogue().object("coffee_mug"), shipped_catalogue().table,
                    PhysicsConfig{});
  const mjModel* m = scene.model();
  EXPECT_TRUE(scene.is_arm_geom(scene.pad_geom));
  EXPECT_TRUE(scene.is_arm_geom(mj_name2id(m, mjOBJ_GEOM, "hand")));
  EXPECT_FALSE(scene.is_arm_geom(scene.table_geom));
  EXPECT_FALSE(scene.is_arm_geom(scene.object_geom));
}

TEST(Scene, EveryPairTheFilterAllowsIsPredefinedWithTheGeomsMixedContactParameters) {
  // The scene skips MuJoCo's broad phase (collision="predefined"): every geom pair the contype/
  // conaffinity filter lets touch must then be a <pair>, or that contact would silently vanish,
  // and each pair must carry what MuJoCo would mix from the two geoms for a dynamic contact
  // (larger friction and condim, mean solref and solimp, larger margin and gap), or the physics
  // would change. The object-table pair is the exception: its friction and stiffness are set.
  const Scene scene(shipped_catalogue().object("coffee_mug"), shipped_catalogue().table,
                    PhysicsConfig{});
  for (const PadContact variant : {PadContact::pushes_object, PadContact::clear_of_object}) {
    const mjModel* m = scene.model(variant);
    EXPECT_EQ(m->opt.collision, mjCOL_PAIR);
    auto find_pair = [&](int a, int b) {
      for (int p = 0; p < m->npair; ++p)
        if ((m->pair_geom1[p] == a && m->pair_geom2[p] == b) ||
            (m->pair_geom1[p] == b && m->pair_geom2[p] == a))
          return p;
      return -1;
    };
    int expected_pairs = 1;  // the object-table pair
    EXPECT_GE(find_pair(scene.table_geom, scene.object_geom), 0);
    for (int a = 0; a < m->ngeom; ++a)
      for (int b = a + 1; b < m->ngeom; ++b) {
        if (m->geom_bodyid[a] == m->geom_bodyid[b]) continue;
        const bool filter = (m->geom_contype[a] & m->geom_conaffinity[b]) ||
                            (m->geom_contype[b] & m->geom_conaffinity[a]);
        const bool object_table = (a == scene.table_geom && b == scene.object_geom) ||
                                  (b == scene.table_geom && a == scene.object_geom);
        if (!filter || object_table) continue;
        ++expected_pairs;
        const int p = find_pair(a, b);
        ASSERT_GE(p, 0) << "geoms " << a << " and " << b << " may touch but are not a pair";
        EXPECT_EQ(m->pair_dim[p], std::max(m->geom_condim[a], m->geom_condim[b]));
        const double* fa = m->geom_friction + 3 * a;
        const double* fb = m->geom_friction + 3 * b;
        const double* f = m->pair_friction + 5 * p;
        EXPECT_EQ(f[0], std::max(fa[0], fb[0]));
        EXPECT_EQ(f[1], std::max(fa[0], fb[0]));
        EXPECT_EQ(f[2], std::max(fa[1], fb[1]));
        EXPECT_EQ(f[3], std::max(fa[2], fb[2]));
        EXPECT_EQ(f[4], std::max(fa[2], fb[2]));
        for (int k = 0; k < mjNREF; ++k)
          EXPECT_DOUBLE_EQ(m->pair_solref[mjNREF * p + k],
                           0.5 * (m->geom_solref[mjNREF * a + k] + m->geom_solref[mjNREF * b + k]));
        for (int k = 0; k < mjNIMP; ++k)
          EXPECT_DOUBLE_EQ(m->pair_solimp[mjNIMP * p + k],
                           0.5 * (m->geom_solimp[mjNIMP * a + k] + m->geom_solimp[mjNIMP * b + k]));
        EXPECT_EQ(m->pair_margin[p], std::max(m->geom_margin[a], m->geom_margin[b]));
        EXPECT_EQ(m->pair_gap[p], std::max(m->geom_gap[a], m->geom_gap[b]));
      }
    EXPECT_EQ(m->npair, expected_pairs);  // and no pair the filter would not allow
  }
}

TEST(Scene, PhysicsTimestepsComeFromTheConfig) {
  PhysicsConfig physics;
  physics.timestep_s = 0.001;
  physics.slide_timestep_s = 0.004;
  const Scene scene(shipped_catalogue().object("paper_base"), shipped_catalogue().table, physics);
  EXPECT_DOUBLE_EQ(scene.model(PadContact::pushes_object)->opt.timestep, 0.004);  // the slide's
  EXPECT_DOUBLE_EQ(scene.model(PadContact::clear_of_object)->opt.timestep, 0.001);
}

TEST(Scene, MujocoWarningsGoToTheLogNotToAFileInTheWorkingDirectory) {
  // MuJoCo's default handler appends to MUJOCO_LOG.TXT in the working directory.
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / fmt::format("echoplan_scene_log_{}", getpid());
  fs::create_directories(dir);
  const fs::path before = fs::current_path();
  fs::current_path(dir);
  const auto sink = std::make_shared<spdlog::sinks::ringbuffer_sink_mt>(16);
  const auto previous = spdlog::default_logger();
  spdlog::set_default_logger(std::make_shared<spdlog::logger>("scene_test", sink));
  {
    const Scene scene(shipped_catalogue().object("coffee_mug"), shipped_catalogue().table,
                      PhysicsConfig{});
    const mjModel* m = scene.model();
    scene.data()->ctrl[0] = std::numeric_limits<double>::quiet_NaN();
    mj_step(m, scene.data());
  }
  spdlog::set_default_logger(previous);
  fs::current_path(before);
  const auto lines = sink->last_formatted();
  EXPECT_TRUE(std::any_of(lines.begin(), lines.end(),
                          [](const std::string& line) {
                            return line.find("MuJoCo: Nan, Inf or huge value in CTRL") !=
                                   std::string::npos;
                          }))
      << lines.size() << " lines logged";
  EXPECT_FALSE(fs::exists(dir / "MUJOCO_LOG.TXT"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace echoplan::sim
