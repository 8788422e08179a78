// TrialLog's files, byte for byte against rows written out by hand from the format in trial_log.h
// (RFC 4180 quoting for names holding separators), read_steps_csv() reading them back, its errors
// on bad files, and summary_json().
#include "experiment/trial_log.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "../common/test_folder.h"
#include "common/error.h"

namespace echoplan::experiment {
namespace {

namespace fs = std::filesystem;

// Two actions (one whose name holds a comma), two objects, two observation symbols.
pomdp::ModelSpec tiger_spec() {
  pomdp::ModelSpec spec;
  spec.name = "tiger";
  spec.action_names = {"listen", "open,left"};
  spec.state.discrete_names = {"tiger"};
  spec.state.discrete_value_names = {{"left", "right"}};
  spec.observation.names = {"hear_left", "hear_right"};
  return spec;
}

// A trial of two steps: listen (heard right, p 0.875), then open,left (heard left).
TrialRecord two_step_trial() {
  TrialRecord t;
  t.trial = 0;
  t.true_state = 1;
  t.believed_state = 1;
  t.steps = 2;
  t.action_counts = {1, 1};
  t.discounted_reward = 8.5;
  return t;
}

std::vector<StepRecord> two_steps() {
  StepRecord listen;
  listen.trial = 0;
  listen.step = 0;
  listen.action = 0;
  listen.observation.index = 1;
  listen.belief = {0.25, 0.75};
  listen.reward = -1;
  listen.episodes = 300;
  listen.heard_probability = 0.875;
  listen.heard_ebr_db = 24.5;
  StepRecord open = listen;
  open.step = 1;
  open.action = 1;
  open.observation.index = 0;
  open.belief = {0.125, 0.875};
  open.reward = 10;
  open.episodes = 200;
  open.heard_probability.reset();
  open.heard_ebr_db.reset();
  return {listen, open};
}

std::string slurp(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

class TrialLogTest : public TestFolder {
 protected:
  fs::path write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name) << text;
    return dir_ / name;
  }

  // The InputError read_steps_csv() throws for `text`; fails the test when it throws none.
  InputError read_error(const std::string& text) {
    const fs::path path = write("steps.csv", text);
    try {
      read_steps_csv(path, tiger_spec());
    } catch (const InputError& e) {
      return e;
    }
    ADD_FAILURE() << "no InputError for:\n" << text;
    return InputError("");
  }
};

TEST_F(TrialLogTest, ParticleCountsAndQuotedNames) {
  {
    TrialLog log(dir_, tiger_spec(), 1000);
    log.trial_finished(two_step_trial(), two_steps());
  }
  EXPECT_EQ(slurp(dir_ / "trials.csv"),
            "trial,true_state,believed_state,steps,n_listen,\"n_open,left\",discounted_reward,"
            "collision\n"
            "0,right,right,2,1,1,8.5,0\n");
  EXPECT_EQ(slurp(dir_ / "steps.csv"),
            "trial,step,action,observation,particles_left,particles_right,reward,episodes,"
            "heard_probability,heard_ebr_db\n"
            "0,0,listen,hear_right,250,750,-1,300,0.875,24.5\n"
            "0,1,\"open,left\",hear_left,125,875,10,200,,\n");
}

TEST_F(TrialLogTest, ProbabilitiesWithoutParticlesAndExtraColumnsOnEveryRow) {
  {
    TrialLog log(dir_, tiger_spec(), 0, {"arm", "object"});
    TrialRecord t = two_step_trial();
    t.believed_state = 0;
    t.collision = true;
    log.write_trial(t, two_steps(), {"abt", "mug \"tall\""});
  }
  EXPECT_EQ(slurp(dir_ / "trials.csv"),
            "trial,true_state,believed_state,steps,n_listen,\"n_open,left\",discounted_reward,"
            "collision,arm,object\n"
            "0,right,left,2,1,1,8.5,1,abt,\"mug \"\"tall\"\"\"\n");
  EXPECT_EQ(slurp(dir_ / "steps.csv"),
            "trial,step,action,observation,p_left,p_right,reward,episodes,heard_probability,"
            "heard_ebr_db,arm,object\n"
            "0,0,listen,hear_right,0.25,0.75,-1,300,0.875,24.5,abt,\"mug \"\"tall\"\"\"\n"
            "0,1,\"open,left\",hear_left,0.125,0.875,10,200,,,abt,\"mug \"\"tall\"\"\"\n");
}

TEST_F(TrialLogTest, OneValuePerExtraColumnIsRequired) {
  TrialLog log(dir_, tiger_spec(), 0, {"arm"});
  EXPECT_THROW(log.write_trial(two_step_trial(), two_steps(), {}), std::invalid_argument);
  EXPECT_THROW(log.write_trial(two_step_trial(), two_steps(), {"a", "b"}), std::invalid_argument);
}

TEST_F(TrialLogTest, ContinuousObservationsAreItsValuesInOneField) {
  pomdp::ModelSpec spec = tiger_spec();
  spec.observation.discrete = false;
  spec.observation.names = {"x", "y"};
  std::vector<StepRecord> steps = {two_steps()[0]};
  steps[0].observation = pomdp::Observation{-1, {0.5, -2}};
  steps[0].heard_probability.reset();
  TrialRecord t = two_step_trial();
  t.steps = 1;
  t.action_counts = {1, 0};
  {
    TrialLog log(dir_, spec, 0);
    log.trial_finished(t, steps);
  }
  const std::string text = slurp(dir_ / "steps.csv");
  EXPECT_EQ(text.substr(text.find('\n') + 1), "0,0,listen,0.5 -2,0.25,0.75,-1,300,,24.5\n");
}

TEST_F(TrialLogTest, AFolderThatCannotBeCreatedIsAnInputError) {
  write("a_file", "");
  EXPECT_THROW(TrialLog(dir_ / "a_file" / "out", tiger_spec(), 0), InputError);
}

TEST_F(TrialLogTest, StepsReadBackAsWritten) {
  {
    TrialLog log(dir_, tiger_spec(), 1000, {"arm"});
    log.write_trial(two_step_trial(), two_steps(), {"x"});
    TrialRecord second = two_step_trial();
    second.trial = 1;
    std::vector<StepRecord> steps = two_steps();
    for (StepRecord& s : steps) s.trial = 1;
    steps[0].reward = -0.5;
    log.write_trial(second, steps, {"y"});
  }
  const auto trials = read_steps_csv(dir_ / "steps.csv", tiger_spec());
  ASSERT_EQ(trials.size(), 2u);
  for (int t = 0; t < 2; ++t) {
    EXPECT_EQ(trials[t].trial, t);
    ASSERT_EQ(trials[t].steps.size(), 2u);
    EXPECT_EQ(trials[t].steps[0].step, 0);
    EXPECT_EQ(trials[t].steps[0].action, 0);       // listen
    EXPECT_EQ(trials[t].steps[0].observation, 1);  // hear_right
    EXPECT_EQ(trials[t].steps[1].step, 1);
    EXPECT_EQ(trials[t].steps[1].action, 1);       // "open,left", quoted in the file
    EXPECT_EQ(trials[t].steps[1].observation, 0);  // hear_left
    EXPECT_EQ(trials[t].steps[1].reward, 10.0);
  }
  EXPECT_EQ(trials[0].steps[0].reward, -1.0);
  EXPECT_EQ(trials[1].steps[0].reward, -0.5);
  // Line numbers: the header is line 1, then trial 0's two rows, then trial 1's.
  EXPECT_EQ(trials[0].steps[0].line, 2);
  EXPECT_EQ(trials[1].steps[1].line, 5);
}

TEST_F(TrialLogTest, ColumnsAreFoundByNameAndRewardIsOptional) {
  const fs::path path = write("steps.csv",
                              "note,observation,action,step,trial\n"
                              "a,hear_left,listen,0,7\n"
                              "\n"
                              "b,hear_right,listen,1,7\r\n");
  const auto trials = read_steps_csv(path, tiger_spec());
  ASSERT_EQ(trials.size(), 1u);
  EXPECT_EQ(trials[0].trial, 7);
  ASSERT_EQ(trials[0].steps.size(), 2u);
  EXPECT_EQ(trials[0].steps[0].observation, 0);
  EXPECT_EQ(trials[0].steps[1].observation, 1);
  EXPECT_EQ(trials[0].steps[1].reward, 0.0);
  EXPECT_EQ(trials[0].steps[1].line, 4);
}

TEST_F(TrialLogTest, BadStepsFilesNameTheLineAndTheProblem) {
  const std::string header = "trial,step,action,observation,reward\n";
  struct Case {
    std::string text;
    int line;
    std::string problem;
  };
  const std::vector<Case> cases = {
      {"trial,step,action,reward\n0,0,listen,1\n", 1, "no 'observation' column in the header"},
      {"", 1, "empty file or broken header"},
      {header + "0,0,listen,hear_left,-1\n0,1,jump,hear_left,-1\n", 3,
       "unknown action 'jump' for this problem"},
      {header + "0,0,listen,roar,-1\n", 2, "unknown observation 'roar' for this problem"},
      {header + "0,0,listen,hear_left\n", 2, "4 fields, the header has 5"},
      {header + "0,0,\"listen,hear_left,-1\n", 2, "unterminated quote"},
      {header + "0,-1,listen,hear_left,-1\n", 2, "step '-1' is not a count >= 0"},
      {header + "x,0,listen,hear_left,-1\n", 2, "trial 'x' is not a count >= 0"},
      {header + "0,0,listen,hear_left,loud\n", 2, "reward 'loud' is not a number"},
      {header + "0,0,listen,hear_left,1.5x\n", 2, "reward '1.5x' is not a number"},
      {header + "0,0,listen,hear_left,-1\n0,2,listen,hear_left,-1\n", 3,
       "trial 0: step 2 where step 1 was expected"},
      {header + "0,0,listen,hear_left,-1\n1,0,listen,hear_left,-1\n0,1,listen,hear_left,-1\n", 4,
       "trial 0 continues after another trial's rows"},
  };
  for (const Case& c : cases) {
    const InputError e = read_error(c.text);
    EXPECT_EQ(e.file(), (dir_ / "steps.csv").string()) << c.text;
    EXPECT_EQ(e.line(), c.line) << c.text;
    EXPECT_EQ(e.problem().substr(0, c.problem.size()), c.problem) << c.text;
  }
  EXPECT_THROW(read_steps_csv(dir_ / "missing.csv", tiger_spec()), InputError);
}

TEST_F(TrialLogTest, SummaryJsonHoldsTheSummaryWithActionsByName) {
  TrialSummary s;
  s.trials = 4;
  s.accuracy = 0.75;
  s.mean_discounted_reward = 2.5;
  s.sd_discounted_reward = 1.25;
  s.ci95 = 1.5;
  s.mean_steps = 3.25;
  s.mean_action_counts = {2.0, 1.0};
  s.collisions = 1;
  s.capped = 2;
  const nlohmann::json expected = {{"trials", 4},
                                   {"accuracy", 0.75},
                                   {"mean_discounted_reward", 2.5},
                                   {"sd_discounted_reward", 1.25},
                                   {"ci95", 1.5},
                                   {"mean_steps", 3.25},
                                   {"collisions", 1},
                                   {"capped", 2},
                                   {"mean_action_counts", {{"listen", 2.0}, {"open,left", 1.0}}}};
  EXPECT_EQ(summary_json(s, tiger_spec()), expected);

  {
    TrialLog log(dir_, tiger_spec(), 0);
    log.write_summary(s, {{"seed", 7}});
  }
  nlohmann::json written = nlohmann::json::parse(slurp(dir_ / "summary.json"));
  EXPECT_EQ(written["run"], nlohmann::json({{"seed", 7}}));
  written.erase("run");
  EXPECT_EQ(written, expected);
}

}  // namespace
}  // namespace echoplan::experiment
