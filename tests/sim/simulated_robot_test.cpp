#include "sim/simulated_robot.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "common/error.h"
#include "shipped_catalogue.h"
#include "sim/recording.h"
#include "sim/scene.h"

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
  const ActionOutcome out = robot.execute(SoundAction::strike, nominal_trial());
  EXPECT_FALSE(out.collision());
  // Lift 0.65 s + pause 0.1 s + descent 0.575 s (each with 0.15 s speed ramps): the grasp holds the
  // object off the table for over 1.2 s.
  EXPECT_GT(longest_airborne(out.trace), 1.2);
  ASSERT_FALSE(out.trace.impacts.empty());
  const Impact& first = out.trace.impacts.front();
  // Grasp 0.1 s + lift 0.65 s + pause 0.1 s + descent of 5 cm at 10 cm/s after a 0.15 s ramp
  // (0.575 s); the servo lags by a few ms.
  EXPECT_NEAR(first.time_s, 1.425, 0.05);
  // Tracking through joint servos is not exact: within 20% of the commanded 0.10 m/s.
  EXPECT_NEAR(first.normal_speed, 0.10, 0.02);
  // The mug's effective mass at its rim is below its mass (it can rotate) but of the same order.
  EXPECT_GT(first.effective_mass, 0.1);
  EXPECT_LE(first.effective_mass, robot.object().total_mass() * 1.0001);
}

TEST(SimulatedRobot, SlidePushesTheObjectAboutFiveCentimetres) {
  for (const char* name : {"coffee_mug", "plastic_cup", "pringles_can", "paper_base"}) {
    SimulatedRobot robot(shipped_catalogue(), name, SimConfig{});
    const ActionOutcome out = robot.execute(SoundAction::slide, nominal_trial());
    EXPECT_FALSE(out.collision()) << name;
    // The pad moves 5.1 cm from 1 mm behind the object; the object may slide on a little after it
    // stops.
    EXPECT_NEAR(out.object_displacement[0], 0.05, 0.01) << name;
    EXPECT_NEAR(out.object_displacement[1], 0.0, 0.01) << name;
    EXPECT_NEAR(out.object_displacement[2], 0.0, 0.002) << name;
    // Pushed, the object stays on the table: force on it nearly all the time.
    const auto touching =
        std::count_if(out.trace.normal_force.begin(), out.trace.normal_force.end(),
                      [](double f) { return f > 0; });
    EXPECT_GT(static_cast<double>(touching) / out.trace.steps, 0.8) << name;
  }
}

TEST(SimulatedRobot, SlideStepsAtTheSlideTimestepAndStrikeAtTheOther) {
  // The synthesis reads each trace at the step it was simulated at: the slide's own and the
  // strike's, both from the config.
  SimConfig config;
  config.physics.timestep_s = 0.002;
  config.physics.slide_timestep_s = 0.0025;
  SimulatedRobot robot(shipped_catalogue(), "coffee_mug", config);
  const ActionOutcome slide = robot.execute(SoundAction::slide, nominal_trial());
  EXPECT_DOUBLE_EQ(slide.trace.timestep_s, 0.0025);
  EXPECT_NEAR(slide.trace.duration_s(), slide.duration_s, 1e-9);
  EXPECT_NEAR(slide.object_displacement[0], 0.05, 0.01);
  const ActionOutcome strike = robot.execute(SoundAction::strike, nominal_trial());
  EXPECT_DOUBLE_EQ(strike.trace.timestep_s, 0.002);
  EXPECT_NEAR(strike.trace.duration_s(), strike.duration_s, 1e-9);
}

// The share of an object's slide covered in the first 30% of the push.
double share_slid_early(const ActionOutcome& out, double push_s) {
  double early = 0, total = 0;
  for (int k = 0; k < out.trace.steps; ++k) {
    const double d = out.trace.sliding_speed[k] * out.trace.timestep_s;
    total += d;
    if ((k + 1) * out.trace.timestep_s <= 0.3 * push_s) early += d;
  }
  return early / total;
}

TEST(SimulatedRobot, SlidePushLastsItsDistanceAtTheMeanSpeedAndBuildsUpOverItsShare) {
  const double push_s = 0.051 / nominal_trial().push_speed;  // 5 cm and the 1 mm pad gap
  SimConfig config;  // accelerates over 40% of the push, decelerates over 20%
  SimulatedRobot robot(shipped_catalogue(), "plastic_cup", config);
  const ActionOutcome slow_start = robot.execute(SoundAction::slide, nominal_trial());
  EXPECT_NEAR(slow_start.duration_s, push_s + 0.05, 0.01);  // and 0.05 s to settle
  EXPECT_NEAR(slow_start.object_displacement[0], 0.05, 0.01);
  // The pad covers 16% of its path in the first 30% of the push (1 mm of it to reach the object).
  EXPECT_LT(share_slid_early(slow_start, push_s), 0.2);

  config.arm.push_accelerate_share = config.arm.push_decelerate_share = 0.1;
  SimulatedRobot quick(shipped_catalogue(), "plastic_cup", config);
  const ActionOutcome quick_start = quick.execute(SoundAction::slide, nominal_trial());
  EXPECT_NEAR(quick_start.duration_s, push_s + 0.05, 0.01);
  EXPECT_NEAR(quick_start.object_displacement[0], 0.05, 0.01);
  EXPECT_GT(share_slid_early(quick_start, push_s), 0.22);  // 28% of the pad's path
}

TEST(SimulatedRobot, HeavierObjectHasLongerContactTime) {
  SimConfig config;
  SimulatedRobot mug(shipped_catalogue(), "coffee_mug", config),
      heavy(shipped_catalogue(), "coffee_mug_weighted", config);
  SoundRenderer mug_recorder(mug.object(), mug.table(), config),
      heavy_recorder(heavy.object(), heavy.table(), config);
  const ActionOutcome a = mug.execute(SoundAction::strike, nominal_trial());
  const ActionOutcome b = heavy.execute(SoundAction::strike, nominal_trial());
  ASSERT_FALSE(a.trace.impacts.empty());
  ASSERT_FALSE(b.trace.impacts.empty());
  EXPECT_GT(b.trace.impacts.front().effective_mass, a.trace.impacts.front().effective_mass * 1.2);
  // tau ~ m^(2/5): 20% more mass is at least 7.5% longer contact.
  EXPECT_GT(heavy_recorder.contact_time(b.trace.impacts.front()),
            mug_recorder.contact_time(a.trace.impacts.front()) * 1.075);
}

TEST(SimulatedRobot, HandDrivenIntoTheTableIsACollision) {
  SimulatedRobot robot(shipped_catalogue(), "coffee_mug", SimConfig{});
  ActionVariation p = nominal_trial();
  p.grasp_height = 0.0;  // fingertips at the table surface
  for (SoundAction action : kSoundActions) {
    const ActionOutcome out = robot.execute(action, p);
    EXPECT_TRUE(out.collision()) << to_string(action);
  }
  // And the same robot is fine at the nominal height in a new trial.
  robot.reset_trial(ObjectPlacement{});
  EXPECT_FALSE(robot.execute(SoundAction::strike, nominal_trial()).collision());
}

TEST(SimulatedRobot, SameParametersGiveTheSameTrace) {
  SimulatedRobot robot(shipped_catalogue(), "pringles_can", SimConfig{});
  Rng a(5), b(5);
  robot.reset_trial(a);
  const ActionOutcome x = robot.execute(SoundAction::strike, a);
  robot.reset_trial(b);
  const ActionOutcome y = robot.execute(SoundAction::strike, b);
  EXPECT_EQ(x.trace.normal_force, y.trace.normal_force);
  EXPECT_EQ(x.trace.sliding_speed, y.trace.sliding_speed);
  ASSERT_EQ(x.trace.impacts.size(), y.trace.impacts.size());
  for (std::size_t i = 0; i < x.trace.impacts.size(); ++i)
    EXPECT_EQ(x.trace.impacts[i].normal_speed, y.trace.impacts[i].normal_speed);
}

TEST(SimulatedRobot, StrikeMakesOneImpact) {
  // Over the variability the lab had (tilt, speed, grasp offset): the hand lowers the object, stops
  // on contact, levels it and opens only after the contact settled, so the object does not bounce
  // and its release makes no second hit. One impact as the contact recorder counts them: its gap
  // test looks at the lowest rim point, so a tilted landing's opposite edge, which touches 10-28 ms
  // later inside the first ring, is not a separate event (docs/simulator.md, "The mug strike").
  for (const char* name :
       {"coffee_mug", "plastic_cup", "pringles_can", "paper_base", "coffee_mug_weighted"}) {
    SimulatedRobot robot(shipped_catalogue(), name, SimConfig{});
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
      Rng rng(seed);
      robot.reset_trial(rng);
      const ActionOutcome out = robot.execute(SoundAction::strike, rng);
      EXPECT_EQ(out.status, ActionStatus::done) << name << " seed " << seed;
      EXPECT_EQ(out.trace.impacts.size(), 1u) << name << " seed " << seed;
    }
  }
}

TEST(SimulatedRobot, SlideMakesNoImpact) {
  // A pushed object slides; its contact with the table is friction only.
  for (const char* name : {"coffee_mug", "plastic_cup"}) {
    SimulatedRobot robot(shipped_catalogue(), name, SimConfig{});
    Rng rng(7);
    robot.reset_trial(rng);
    EXPECT_TRUE(robot.execute(SoundAction::slide, rng).trace.impacts.empty()) << name;
  }
}

TEST(SimulatedRobot, ChainedSlideMovesTheObjectAndTheNextActionStartsThere) {
  SimulatedRobot robot(shipped_catalogue(), "plastic_cup", SimConfig{});
  robot.reset_trial(ObjectPlacement{});
  const auto before = robot.object_position();
  const ActionOutcome first = robot.execute(SoundAction::slide, nominal_trial());
  ASSERT_EQ(first.status, ActionStatus::done);
  const auto after = robot.object_position();
  EXPECT_NEAR(after[0] - before[0], 0.05, 0.003);
  EXPECT_NEAR(after[1] - before[1], 0.0, 0.003);
  // The second slide starts where the first left the object and pushes it 5 cm further.
  const ActionOutcome second = robot.execute(SoundAction::slide, nominal_trial());
  ASSERT_EQ(second.status, ActionStatus::done);
  for (int k = 0; k < 3; ++k) EXPECT_DOUBLE_EQ(second.object_start[k], after[k]);
  EXPECT_NEAR(robot.object_position()[0] - before[0], 0.10, 0.006);
  // A strike after them lifts it from there and puts it back down there.
  const ActionOutcome strike = robot.execute(SoundAction::strike, nominal_trial());
  EXPECT_EQ(strike.status, ActionStatus::done);
  EXPECT_NEAR(strike.object_start[0] - before[0], 0.10, 0.006);
  EXPECT_NEAR(std::hypot(strike.object_displacement[0], strike.object_displacement[1]), 0.0, 0.002);
  // A new trial puts it back at its nominal place.
  robot.reset_trial(ObjectPlacement{});
  EXPECT_EQ(robot.object_position(), before);
}

TEST(SimulatedRobot, ObjectPushedOutOfReachIsAnOutcomeNotACrash) {
  SimulatedRobot robot(shipped_catalogue(), "pringles_can", SimConfig{});
  robot.reset_trial(ObjectPlacement{});
  ActionOutcome out;
  int slides = 0;
  do {
    out = robot.execute(SoundAction::slide, nominal_trial());
    ++slides;
  } while (out.status == ActionStatus::done && slides < 50);
  // The arm reaches about 1 m from its shoulder; the object starts 0.5 m away and moves 5 cm a
  // slide.
  EXPECT_NE(out.status, ActionStatus::done) << "50 slides of 5 cm stayed within reach";
  EXPECT_FALSE(out.reason.empty());
}

// Every byte of an mjModel's buffer (all its arrays) and its option and size fields.
std::vector<unsigned char> model_bytes(const mjModel* m) {
  std::vector<unsigned char> bytes(static_cast<const unsigned char*>(m->buffer),
                                   static_cast<const unsigned char*>(m->buffer) + m->nbuffer);
  const auto* opt = reinterpret_cast<const unsigned char*>(&m->opt);
  bytes.insert(bytes.end(), opt, opt + sizeof m->opt);
  return bytes;
}

TEST(SimulatedRobot, ModelIsUnchangedByATrial) {
  SimulatedRobot robot(shipped_catalogue(), "coffee_mug", SimConfig{});
  const std::vector<unsigned char> push =
      model_bytes(robot.scene().model(PadContact::pushes_object));
  const std::vector<unsigned char> clear =
      model_bytes(robot.scene().model(PadContact::clear_of_object));
  Rng rng(3);
  robot.reset_trial(rng);
  for (SoundAction action :
       {SoundAction::slide, SoundAction::strike, SoundAction::slide, SoundAction::strike})
    robot.execute(action, rng);
  EXPECT_TRUE(model_bytes(robot.scene().model(PadContact::pushes_object)) == push);
  EXPECT_TRUE(model_bytes(robot.scene().model(PadContact::clear_of_object)) == clear);
}

TEST(SimulatedRobot, UnknownObjectIsAnInputError) {
  EXPECT_THROW(SimulatedRobot(shipped_catalogue(), "teapot", SimConfig{}), InputError);
}

}  // namespace
}  // namespace echoplan::sim
