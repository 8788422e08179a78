// What `echoplan run` and the ROS planner node print for a step and a belief.
#include "loop/step_text.h"

#include <gtest/gtest.h>

namespace echoplan::loop {
namespace {

pomdp::ModelSpec spec() {
  pomdp::ModelSpec s;
  s.action_names = {"slide", "strike", "move_to_A"};
  s.observation.names = {"coffee_mug", "plastic_cup", "unknown", "none"};
  return s;
}

Step heard(const std::string& label, bool unknown) {
  Step s;
  s.record.step = 1;
  s.record.action = 1;
  s.record.reward = -1;
  RobotStep& r = s.robot.emplace();
  r.report = {
      .action = "strike", .status = robot::ActionStatus::done, .reason = "", .duration_s = 0.5};
  r.classified = true;
  r.heard.label = label;
  r.heard.unknown = unknown;
  r.heard.probability = 0.875;
  r.heard.probabilities = {{"coffee_mug", 0.875}, {"plastic_cup", 0.125}};
  r.observe_ms = 1.25;
  return s;
}

TEST(StepText, SaysWhatWasHeardWithItsProbabilityAndTime) {
  EXPECT_EQ(step_text(heard("coffee_mug", false), spec()),
            "step 2: strike -> heard coffee_mug (p 0.88), 1.2 ms to classify, reward -1");
  EXPECT_EQ(step_text(heard("unknown", true), spec()),
            "step 2: strike -> heard unknown (nearest coffee_mug, p 0.88), 1.2 ms to classify, "
            "reward -1");
}

TEST(StepText, SaysHowAFailedActionWentAndWhatATableWorldObserved) {
  Step s = heard("coffee_mug", false);
  s.robot->report = {.action = "strike",
                     .status = robot::ActionStatus::collision,
                     .reason = "the arm touched the table",
                     .duration_s = 0.2};
  s.record.reward = -100;
  EXPECT_EQ(step_text(s, spec()),
            "step 2: strike -> collision: the arm touched the table, reward -100");
  Step table;
  table.record.action = 0;
  table.record.observation.index = 1;
  table.record.reward = -1;
  EXPECT_EQ(step_text(table, spec()), "step 1: slide -> observed plastic_cup, reward -1");
}

TEST(StepText, SaysAStepsFaultInsteadOfWhatWasHeard) {
  Step s = heard("coffee_mug", false);
  s.robot->classified = false;
  s.robot->fault = StepFault{"recording silent", "peak 0", FaultEffect::observation_skipped};
  EXPECT_EQ(step_text(s, spec()), "step 2: strike -> recording silent: peak 0, reward -1");
}

TEST(StepText, SaysHowATrialEnded) {
  pomdp::ModelSpec s = spec();
  s.state.discrete_value_names = {{"coffee_mug", "plastic_cup"}};
  Trial trial;
  trial.steps.resize(2);
  trial.steps[1].record.action = 2;
  trial.record.steps = 2;
  trial.record.believed_state = 1;
  trial.record.discounted_reward = 8.9;
  EXPECT_EQ(trial_text(trial, s),
            "sorted by move_to_A (believed plastic_cup); 2 steps, discounted reward 8.900");
  trial.record.collision = true;
  trial.record.discounted_reward = -101;
  EXPECT_EQ(trial_text(trial, s), "ended in a collision; 2 steps, discounted reward -101.000");
  trial.record.collision = false;
  trial.record.capped = true;
  EXPECT_EQ(trial_text(trial, s).substr(0, 37), "no sorting action within the step cap");
}

TEST(StepText, ABeliefIsOneAlignedLinePerObject) {
  EXPECT_EQ(belief_text({"mug", "cup"}, {0.25, 0.75}),
            "    mug  ██████░░░░░░░░░░░░░░░░░░  0.250\n"
            "    cup  ██████████████████░░░░░░  0.750\n");
}

}  // namespace
}  // namespace echoplan::loop
