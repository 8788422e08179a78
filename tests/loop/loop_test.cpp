// The Loop and its checked specification: what every caller (run, trials, the ROS node, a
// campaign's workers) relies on.
#include "loop/loop.h"

#include <gtest/gtest.h>

#include "../common/input_error_message.h"
#include "../common/source_dir.h"
#include "common/error.h"
#include "pomdp/problem.h"

namespace echoplan::loop {
namespace {

std::shared_ptr<const pomdp::Problem> shipped(const std::string& name) {
  return std::make_shared<const pomdp::Problem>(
      pomdp::load_problem(echoplan::testing::source_dir() + "/problems/" + name));
}

LoopSettings table_settings() {
  LoopSettings s;
  s.problem = shipped("audio_objects.yaml");
  s.planner.episodes = 200;
  return s;
}

std::shared_ptr<const LoopSpec> spec(LoopSettings s) {
  return std::make_shared<const LoopSpec>(std::move(s));
}

bool mentions(const std::string& message, const std::string& what) {
  return message.find(what) != std::string::npos;
}

TEST(LoopSpec, BadSettingsAreInputErrorsBeforeAnyTrial) {
  LoopSettings s = table_settings();
  s.max_steps = 0;
  EXPECT_TRUE(mentions(input_error_message([&] { spec(s); }), "--max-steps"));
  s = table_settings();
  s.planner.solver = "despot";
  EXPECT_TRUE(mentions(input_error_message([&] { spec(s); }), "'despot'"));
  s = table_settings();
  s.planner.policy = "policy.json";
  EXPECT_TRUE(mentions(input_error_message([&] { spec(s); }), "--policy is for --solver offline"));
}

TEST(LoopSpec, ThePlannersProblemAndTheWorldsMustShareTheirNames) {
  LoopSettings s = table_settings();
  s.world_problem = shipped("tiger.pomdp");
  EXPECT_TRUE(mentions(input_error_message([&] { spec(s); }), "tiger.pomdp"));
}

TEST(Loop, TheSameRequestGivesTheSameTrialAndAnotherSeedAnother) {
  const auto shared = spec(table_settings());
  Loop a(shared), b(shared);
  const auto first = a.run({3, 1, 11});
  a.run({4, -1, 11});  // what ran before does not matter
  const auto again = a.run({3, 1, 11});
  const auto elsewhere = b.run({3, 1, 11});
  ASSERT_TRUE(first && again && elsewhere);
  for (const auto* t : {&*again, &*elsewhere}) {
    ASSERT_EQ(t->steps.size(), first->steps.size());
    for (std::size_t i = 0; i < first->steps.size(); ++i) {
      EXPECT_EQ(t->steps[i].record.action, first->steps[i].record.action);
      EXPECT_EQ(t->steps[i].record.observation, first->steps[i].record.observation);
      EXPECT_EQ(t->steps[i].record.belief, first->steps[i].record.belief);
    }
    EXPECT_EQ(t->record.discounted_reward, first->record.discounted_reward);
  }
  EXPECT_EQ(first->record.true_state, 1);
  EXPECT_EQ(first->record.trial, 3);
}

TEST(Loop, EachStepCarriesTheBeliefAfterItAndTheTableWorldHasNoRobot) {
  Loop loop(spec(table_settings()));
  int seen = 0;
  const auto trial = loop.run({0, 2, 5}, [&](const Step&) { ++seen; });
  ASSERT_TRUE(trial);
  EXPECT_EQ(seen, static_cast<int>(trial->steps.size()));
  for (std::size_t i = 0; i + 1 < trial->steps.size(); ++i) {
    ASSERT_TRUE(trial->steps[i].belief_after.has_value()) << i;
    EXPECT_EQ(*trial->steps[i].belief_after, trial->steps[i + 1].record.belief) << i;
    EXPECT_FALSE(trial->steps[i].robot.has_value());
  }
  EXPECT_TRUE(trial->steps.back().terminal);
  EXPECT_FALSE(trial->steps.back().belief_after.has_value());
}

TEST(Loop, AStopRequestDropsTheTrialInProgress) {
  Loop loop(spec(table_settings()));
  std::atomic<bool> stop{false};
  const auto trial = loop.run(
      {0, 0, 5}, [&](const Step&) { stop = true; }, &stop);
  EXPECT_FALSE(trial.has_value());
}

TEST(Loop, ObjectIndexNamesTheProblemsObjectsWhenTheObjectIsNotOne) {
  const auto problem = shipped("audio_objects.yaml");
  EXPECT_EQ(object_index(*problem, "plastic_cup"), 2);
  const std::string e = input_error_message([&] { object_index(*problem, "teapot"); });
  EXPECT_TRUE(mentions(e, "'teapot'") && mentions(e, "coffee_mug")) << e;
}

}  // namespace
}  // namespace echoplan::loop
