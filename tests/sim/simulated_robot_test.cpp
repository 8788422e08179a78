#include "sim/simulated_robot.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "common/error.h"
#include "sim/simulated_recorder.h"

#include "shipped_catalogue.h"

namespace echoplan::sim {
namespace {

// The longest stretch (s) with no object-table force.
double longest_airborne(const ContactTrace& t) {
  int best = 0, run = 0;
  for (double f : t.normal_force) {
    run = f > 0 ? 0 : run + 1;
    best = std::max(best, run);
  }
  return best * t.timestep_s;
}

TEST(SimulatedRobot, StrikeLiftsTheObjectAndBringsItDownAtTheCommandedSpeed) {
  SimulatedRobot robot(shipped_catalogue(), "coffee_mug", SimConfig{});
  const ActionOutcome out = robot.execute("strike", nominal_trial());
  EXPECT_FALSE(out.collision);
  // Lift 0.5 s + pause 0.1 s + descent 0.5 s: the weld holds the object off the table for over 0.9 s.
  EXPECT_GT(longest_airborne(out.trace), 0.9);
  ASSERT_FALSE(out.trace.impacts.empty());
  const Impact& first = out.trace.impacts.front();
  // Grasp 0.1 s + lift 0.5 s + pause 0.1 s + descent of 5 cm at 10 cm/s; the servo lags by a few ms.
  EXPECT_NEAR(first.time_s, 1.2, 0.05);
  // Tracking through joint servos is not exact: within 20% of the commanded 0.10 m/s.
  EXPECT_NEAR(first.normal_speed, 0.10, 0.02);
  // The mug's effective mass at its rim is below its mass (it can rotate) but of the same order.
  EXPECT_GT(first.effective_mass, 0.1);
  EXPECT_LE(first.effective_mass, robot.object().total_mass() * 1.0001);
}

TEST(SimulatedRobot, SlidePushesTheObjectAboutFiveCentimetres) {
  for (const char* name : {"coffee_mug", "plastic_cup", "pringles_can", "paper_base"}) {
    SimulatedRobot robot(shipped_catalogue(), name, SimConfig{});
    const ActionOutcome out = robot.execute("slide", nominal_trial());
    EXPECT_FALSE(out.collision) << name;
    // The pad moves 5.1 cm from 1 mm behind the object; the object may slide on a little after it stops.
    EXPECT_NEAR(out.object_displacement[0], 0.05, 0.01) << name;
    EXPECT_NEAR(out.object_displacement[1], 0.0, 0.01) << name;
    EXPECT_NEAR(out.object_displacement[2], 0.0, 0.002) << name;
    // Pushed, the object stays on the table: force on it nearly all the time.
    const auto touching = std::count_if(out.trace.normal_force.begin(), out.trace.normal_force.end(),
                                        [](double f) { return f > 0; });
    EXPECT_GT(static_cast<double>(touching) / out.trace.steps, 0.8) << name;
  }
}

TEST(SimulatedRobot, HeavierObjectHasLongerContactTime) {
  SimConfig config;
  SimulatedRobot mug(shipped_catalogue(), "coffee_mug", config), heavy(shipped_catalogue(), "coffee_mug_weighted", config);
  SimulatedRecorder mug_recorder(mug.object(), mug.table(), config), heavy_recorder(heavy.object(), heavy.table(), config);
  const ActionOutcome a = mug.execute("strike", nominal_trial());
  const ActionOutcome b = heavy.execute("strike", nominal_trial());
  ASSERT_FALSE(a.trace.impacts.empty());
  ASSERT_FALSE(b.trace.impacts.empty());
  EXPECT_GT(b.trace.impacts.front().effective_mass, a.trace.impacts.front().effective_mass * 1.2);
  // tau ~ m^(2/5): 20% more mass is at least 7.5% longer contact.
  EXPECT_GT(heavy_recorder.contact_time(b.trace.impacts.front()), mug_recorder.contact_time(a.trace.impacts.front()) * 1.075);
}

TEST(SimulatedRobot, HandDrivenIntoTheTableIsACollision) {
  SimulatedRobot robot(shipped_catalogue(), "coffee_mug", SimConfig{});
  TrialParameters p = nominal_trial();
  p.grasp_height = 0.0;  // fingertips at the table surface
  for (const char* action : {"slide", "strike"}) {
    const ActionOutcome out = robot.execute(action, p);
    EXPECT_TRUE(out.collision) << action;
  }
  // And the same robot afterwards is fine at the nominal height (execute resets the scene).
  EXPECT_FALSE(robot.execute("strike", nominal_trial()).collision);
}

TEST(SimulatedRobot, SameParametersGiveTheSameTrace) {
  SimulatedRobot robot(shipped_catalogue(), "pringles_can", SimConfig{});
  Rng a(5), b(5);
  const ActionOutcome x = robot.execute("strike", a);
  const ActionOutcome y = robot.execute("strike", b);
  EXPECT_EQ(x.trace.normal_force, y.trace.normal_force);
  EXPECT_EQ(x.trace.sliding_speed, y.trace.sliding_speed);
  ASSERT_EQ(x.trace.impacts.size(), y.trace.impacts.size());
  for (std::size_t i = 0; i < x.trace.impacts.size(); ++i)
    EXPECT_EQ(x.trace.impacts[i].normal_speed, y.trace.impacts[i].normal_speed);
}

TEST(SimulatedRobot, UnknownActionIsAnInputError) {
  SimulatedRobot robot(shipped_catalogue(), "coffee_mug", SimConfig{});
  Rng rng(1);
  EXPECT_THROW(robot.execute("juggle", rng), InputError);
  EXPECT_THROW(SimulatedRobot(shipped_catalogue(), "teapot", SimConfig{}), InputError);
}

}  // namespace
}  // namespace echoplan::sim
