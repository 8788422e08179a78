// parse_oppt_log() on logs written here in OPPT's layout (the reference "original-robot-runs.md",
// "The OPPT run-log format"): several runs per file, the repeated last step, empty particle blocks,
// each bad input's error and line; oppt_run_records() against rewards and beliefs computed by hand.
#include "experiment/oppt_log.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "../common/source_dir.h"
#include "common/error.h"

namespace echoplan::experiment {
namespace {

const std::string kProblem = echoplan::testing::source_dir() + "/problems/audio_objects.yaml";
const std::string kState = "-2.89 1.45 -0.18 2.07 -0.31 0.63 -1.54 0.1 0 0";

std::string state_line(const char* key, int object, const char* weight) {
  return std::string(key) + " " + kState + " " + std::to_string(object) + " w: " + weight +
         " END USER_DATA_BEGIN : 0 0 USER_DATA_END\n";
}

// One "t = " block: particles_after lists the particles' objects (empty: an empty block).
std::string step(int t, int object, int action, int observation, double reward,
                 const std::vector<int>& particles_after, int histories = 500) {
  std::string s = "t = " + std::to_string(t) + "\n" + state_line("S:", object, "1");
  s += "A: " + std::to_string(action) + " END\nO: " + std::to_string(observation) + " END\n";
  s += "IMMEDIATE_REWARD: " + std::to_string(reward) + "\nDISCOUNT_FACTOR: 1\n";
  s += "DISCOUNTED_REWARD: " + std::to_string(reward) + "\nPARTICLES BEGIN\n";
  for (int p : particles_after) s += state_line("p:", p, "0.001");
  s += "PARTICLES END\nSOLVER_DATA_BEGIN\nNUM HISTORIES: " + std::to_string(histories) +
       "\nTotalTreeDepth: 3\nSOLVER_DATA_END\n";
  return s;
}

// The last step written a second time with the final state, then the run's trailer.
std::string last_step_and_trailer(int t, int object, int action, double total, int num_steps) {
  std::string s = "t = " + std::to_string(t) + "\n" + state_line("S:", object, "1");
  s += "A: " + std::to_string(action) + " END\nO: 5 END\nIMMEDIATE_REWARD: 10\n";
  s += "DISCOUNT_FACTOR: 0.99\nDISCOUNTED_REWARD: 9.9\nFINAL_STATE_BEGIN\n" +
       state_line("S:", object, "1") + "FINAL_STATE_END\nPARTICLES BEGIN\nPARTICLES END\n";
  s += "Total discounted reward: " + std::to_string(total) + "\nRun successful: False\n";
  s += "Num steps: " + std::to_string(num_steps) + "\nTotal time taken: 10341.41ms\n";
  return s;
}

const std::string kHeader = "seed: 1234\nRobot: movo\nsolver: ABT\n";
const std::string kFooter =
    "##################################\nMean number of steps: 2\nMean planning time per step: "
    "2004.33ms\n";

// The reference's mug run "strike move_to_B", heard "coffee_mug -": 2 particles of the mug and
// one of the cup logged after the strike.
std::string mug_run(int number) {
  return "Run #" + std::to_string(number) + "\n" + step(0, 1, 5, 1, -1, {1, 1, 2}, 512) +
         step(1, 1, 7, 5, 10, {}, 930) + last_step_and_trailer(1, 1, 7, 8.9, 2);
}

// The reference's paper base run "slide strike slide slide move_to_B", heard "coffee_mug
// paper_base paper_base paper_base -"; the block after the first slide is empty.
std::string paper_base_run(int number) {
  return "Run #" + std::to_string(number) + "\n" + step(0, 3, 4, 1, -1, {}) +
         step(1, 3, 5, 3, -1, {3, 3, 3, 1}) + step(2, 3, 4, 3, -1, {3}) +
         step(3, 3, 4, 3, -1, {3, 3}) + step(4, 3, 7, 5, 10, {}) +
         last_step_and_trailer(4, 3, 7, 5.66556, 5);
}

OpptCodes report_codes(const pomdp::Problem& problem) {
  const pomdp::ModelSpec& spec = problem.model->spec();
  OpptCodes codes;
  codes.actions = parse_code_mapping("4=slide,5=strike,6=move_to_A,7=move_to_B", spec.action_names,
                                     "--actions");
  codes.observations =
      parse_code_mapping("0=pringles_can,1=coffee_mug,2=plastic_cup,3=paper_base,5=none",
                         spec.observation.names, "--observations");
  codes.objects = parse_code_mapping("0=pringles_can,1=coffee_mug,2=plastic_cup,3=paper_base",
                                     spec.state.discrete_value_names[0], "--objects");
  return codes;
}

// The line number and message of the InputError parsing `text` throws.
std::pair<int, std::string> parse_error(const std::string& text) {
  try {
    parse_oppt_log(text, "run.log");
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "run.log");
    return {e.line(), e.problem()};
  }
  ADD_FAILURE() << "no InputError for:\n" << text;
  return {-1, ""};
}

TEST(OpptLog, ReadsSeveralRunsAndDropsTheRepeatedLastStep) {
  const auto runs = parse_oppt_log(kHeader + mug_run(1) + paper_base_run(2) + kFooter, "run.log");
  ASSERT_EQ(runs.size(), 2u);
  EXPECT_EQ(runs[0].number, 1);
  EXPECT_EQ(runs[0].line, 4);
  ASSERT_EQ(runs[0].steps.size(), 2u);  // t = 1 was written twice
  EXPECT_EQ(runs[0].steps[0].action, 5);
  EXPECT_EQ(runs[0].steps[0].observation, 1);
  EXPECT_EQ(runs[0].steps[0].true_object, 1);
  EXPECT_EQ(runs[0].steps[0].immediate_reward, -1.0);
  EXPECT_EQ(runs[0].steps[0].histories, 512);
  EXPECT_EQ(runs[0].steps[1].histories, 930);
  EXPECT_EQ(runs[0].steps[1].line, 21);  // t = 0 at line 5 and its 16 lines (3 particles)
  ASSERT_TRUE(runs[0].steps[0].particles_after.has_value());
  EXPECT_EQ(*runs[0].steps[0].particles_after, (std::map<int, int>{{1, 2}, {2, 1}}));
  EXPECT_DOUBLE_EQ(runs[0].total_discounted_reward, 8.9);
  EXPECT_EQ(runs[0].num_steps, 2);
  EXPECT_EQ(runs[1].number, 2);
  ASSERT_EQ(runs[1].steps.size(), 5u);
  EXPECT_TRUE(runs[1].steps[0].particles_after->empty());  // an empty block
  EXPECT_EQ(runs[1].steps[4].action, 7);
}

TEST(OpptLog, StepLinesAreCounted) {
  // Run #1 at line 4, its t = 0 at line 5; that step holds 13 lines + 3 particles = 16 lines.
  const auto runs = parse_oppt_log(kHeader + mug_run(1), "run.log");
  EXPECT_EQ(runs[0].steps[0].line, 5);
  EXPECT_EQ(runs[0].steps[1].line, 21);
  EXPECT_EQ(runs[0].steps[0].particles_line, 12);
}

TEST(OpptLog, RecordsOfTheMugRunMatchTheReference) {
  const pomdp::Problem problem = pomdp::load_problem(kProblem);
  const auto runs = parse_oppt_log(mug_run(1), "run.log");
  BeliefSources sources;
  const TrialResult t =
      oppt_run_records(runs[0], report_codes(problem), problem, 7, "run.log", sources);
  // Hand-computed: -1 + 0.99 * 10, the reference's 8.9.
  EXPECT_NEAR(t.record.discounted_reward, 8.9, 1e-12);
  EXPECT_EQ(t.record.trial, 7);
  EXPECT_EQ(t.record.true_state, 1);      // coffee_mug
  EXPECT_EQ(t.record.believed_state, 1);  // 2 of the 3 particles
  EXPECT_EQ(t.record.steps, 2);
  EXPECT_EQ(t.record.action_counts, (std::vector<int>{0, 1, 0, 1}));
  ASSERT_EQ(t.steps.size(), 2u);
  EXPECT_EQ(t.steps[0].action, 1);  // strike
  EXPECT_EQ(t.steps[0].observation.index, 1);
  EXPECT_EQ(t.steps[1].action, 3);             // move_to_B
  EXPECT_EQ(t.steps[1].observation.index, 4);  // none
  EXPECT_EQ(t.steps[1].episodes, 930);
  // Step 0: the problem's uniform prior; step 1: the 3 logged particles out of 1000.
  EXPECT_EQ(t.steps[0].belief, (std::vector<double>{0.25, 0.25, 0.25, 0.25}));
  EXPECT_EQ(t.steps[1].belief, (std::vector<double>{0.0, 0.002, 0.001, 0.0}));
  EXPECT_EQ(sources.initial, 1);
  EXPECT_EQ(sources.particles, 1);
  EXPECT_EQ(sources.exact, 0);
}

TEST(OpptLog, AnEmptyBlockGivesTheProblemsExactBelief) {
  const pomdp::Problem problem = pomdp::load_problem(kProblem);
  const auto runs = parse_oppt_log(paper_base_run(1), "run.log");
  BeliefSources sources;
  const TrialResult t =
      oppt_run_records(runs[0], report_codes(problem), problem, 0, "run.log", sources);
  // -1 - 0.99 - 0.99^2 - 0.99^3 + 10 * 0.99^4 = 5.6655611, the reference's 5.66556.
  EXPECT_NEAR(t.record.discounted_reward, 5.6655611, 1e-9);
  // After a slide heard as the mug from the uniform prior: the slide table's coffee_mug column
  // (0.3, 0.67, 0.11, 0.01) normalised by its sum 1.09.
  ASSERT_EQ(t.steps[1].belief.size(), 4u);
  EXPECT_NEAR(t.steps[1].belief[0], 0.3 / 1.09, 1e-12);
  EXPECT_NEAR(t.steps[1].belief[1], 0.67 / 1.09, 1e-12);
  EXPECT_NEAR(t.steps[1].belief[3], 0.01 / 1.09, 1e-12);
  EXPECT_EQ(t.steps[2].belief, (std::vector<double>{0.0, 0.001, 0.0, 0.003}));
  EXPECT_EQ(t.record.believed_state, 3);  // paper_base: the 2 particles logged after step 3
  EXPECT_EQ(sources.initial, 1);
  EXPECT_EQ(sources.exact, 1);
  EXPECT_EQ(sources.particles, 3);
}

TEST(OpptLog, ACodeWithoutAMappingNamesTheFlagAndLine) {
  const pomdp::Problem problem = pomdp::load_problem(kProblem);
  OpptCodes codes = report_codes(problem);
  codes.actions.erase(5);
  const auto runs = parse_oppt_log(mug_run(1), "run.log");
  BeliefSources sources;
  try {
    oppt_run_records(runs[0], codes, problem, 0, "run.log", sources);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 2);
    EXPECT_NE(e.problem().find("action code 5 has no --actions mapping"), std::string::npos);
  }
  codes = report_codes(problem);
  codes.objects.erase(2);  // a particle of object 2 is logged after step 0 (line 9)
  try {
    oppt_run_records(runs[0], codes, problem, 0, "run.log", sources);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 9);
    EXPECT_NE(e.problem().find("--objects"), std::string::npos);
  }
}

TEST(OpptLog, BadInputNamesItsLine) {
  const std::string run = "Run #1\n";
  struct Case {
    std::string text;
    int line;
    std::string message;
  };
  const std::string good0 = step(0, 1, 5, 1, -1, {});  // 13 lines: 2 to 14 after "Run #1"
  const std::vector<Case> cases = {
      {kHeader + step(0, 1, 5, 1, -1, {}), 4, "a step before any 'Run #'"},
      {run + "t = 0\nS: " + kState + " 1 w: 1 END\nA: 4 END\nO: 1 END\nIMMEDIATE_REWARD: abc\n", 6,
       "IMMEDIATE_REWARD: 'abc' is not a number"},
      {run + "t = 0\nS: " + kState + " x w: 1 END\n", 3, "object (the state's last number) 'x'"},
      {run + "t = 0\nA: 4\n", 3, "'A:' has no END"},
      {run + good0, 14, "run #1 (line 1) ends without 'Total discounted reward:'"},
      {run + "t = 0\nPARTICLES BEGIN\n" + state_line("p:", 1, "1"), 4,
       "PARTICLES BEGIN at line 3 has no PARTICLES END"},
      {run + "t = 0\nPARTICLES BEGIN\nt = 1\n", 4, "inside the particles block of line 3"},
      {run + "t = 0\nSOLVER_DATA_BEGIN\nt = 1\n", 4, "SOLVER_DATA_BEGIN at line 3 has no"},
      {run + "t = 0\nA: 4 END\nO: 1 END\nIMMEDIATE_REWARD: -1\nt = 1\n", 2,
       "step t = 0 has no 'S:' line"},
      {run + step(1, 1, 5, 1, -1, {}) + "Total discounted reward: 1\n", 2,
       "step t = 1 where t = 0 was expected"},
      {run + good0 + step(0, 1, 4, 1, -1, {}) + "Total discounted reward: 1\n", 15,
       "step t = 0 is repeated with other contents than at line 2"},
      {run + good0 + "Total discounted reward: -1\nNum steps: 2\n", 16,
       "'Num steps: 2' but run #1 has 1 steps"},
      {run + "Total discounted reward: 0\n", 1, "run #1 has no steps"},
      {run + good0 + "Total discounted reward: -1\n" + step(1, 1, 5, 1, -1, {}), 16,
       "a step after the run's 'Total discounted reward'"},
      {"A: 4 END\n", 1, "'A:' outside a step"},
      {kHeader, 3, "no 'Run #' in the log"},
      {"Run #x\n", 1, "run number 'x' is not an integer"},
  };
  for (const Case& c : cases) {
    const auto [line, message] = parse_error(c.text);
    EXPECT_EQ(line, c.line) << c.message << " in:\n" << c.text;
    EXPECT_NE(message.find(c.message), std::string::npos)
        << "'" << message << "' lacks '" << c.message << "'";
  }
}

TEST(OpptLog, MappingsAreCheckedAgainstTheProblemsNames) {
  const std::vector<std::string> names = {"slide", "strike"};
  EXPECT_EQ(parse_code_mapping("4=slide,5=strike", names, "--actions"),
            (std::map<int, int>{{4, 0}, {5, 1}}));
  const auto message = [&](const std::string& text) {
    try {
      parse_code_mapping(text, names, "--actions");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message("4=slid").find("--actions: 'slid' is not one of the problem's names (slide, "
                                   "strike)"),
            std::string::npos);
  EXPECT_NE(message("4:slide").find("--actions: '4:slide' is not CODE=NAME"), std::string::npos);
  EXPECT_NE(message("a=slide").find("code 'a' is not an integer"), std::string::npos);
  EXPECT_NE(message("4=slide,4=strike").find("code 4 is mapped twice"), std::string::npos);
  EXPECT_NE(message("").find("no CODE=NAME pairs"), std::string::npos);
}

}  // namespace
}  // namespace echoplan::experiment
