// `echoplan train --data DIR --problem-out FILE` on generated feature sets, at the issue's scale
// (100 objects x 9 behaviours x 20 groups of 5, five sessions each), run as a user would.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <fstream>

#include "../common/source_dir.h"
#include "../perception/synthetic_feature_set.h"
#include "pomdp/object_identification_model.h"
#include "pomdp/problem.h"

namespace echoplan {
namespace {
namespace fs = std::filesystem;
using perception::test_features::SyntheticSpec;

struct CommandResult {
  int status = -1;
  std::string out, err;
  double seconds = 0.0;
};

CommandResult run(const std::string& args) {
  const fs::path dir = perception::test_features::fresh_folder("train_cli_out");
  const std::string command = "'" + echoplan::testing::echoplan_binary() + "' " + args + " > '" +
                              (dir / "out").string() + "' 2> '" + (dir / "err").string() + "'";
  const auto start = std::chrono::steady_clock::now();
  const int raw = std::system(command.c_str());
  CommandResult r;
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  auto slurp = [](const fs::path& p) {
    std::ifstream in(p);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  };
  r.out = slurp(dir / "out");
  r.err = slurp(dir / "err");
  return r;
}

// 100 objects in 20 groups of 5, 9 behaviours, 5 sessions; audio (40 features) tells objects
// apart, haptic (10 features) is pure noise.
fs::path issue_scale_set() {
  static const fs::path dir = [] {
    const fs::path d = perception::test_features::fresh_folder("train_cli_set");
    SyntheticSpec spec;
    spec.objects = 100;
    spec.group_size = 5;
    spec.group_separation = 1.0;
    spec.actions = {"drop", "grasp", "hold", "lift", "lower", "poke", "press", "push", "shake"};
    spec.modalities = {{"audio", 40, 0.6}, {"haptic", 10, 0.0}};
    perception::test_features::write_synthetic_feature_set(d, spec);
    return d;
  }();
  return dir;
}

TEST(TrainDatasetCli, WritesTheProblemOfAHundredObjectsInTwentyGroups) {
  const fs::path set = issue_scale_set();
  const fs::path problem =
      set.parent_path() / ("train_cli_" + std::to_string(::getpid()) + ".yaml");
  const auto r = run("train --data '" + set.string() + "' --groups '" +
                     (set / "groups.csv").string() + "' --problem-out '" + problem.string() + "'");
  ASSERT_EQ(r.status, 0) << r.err;
  std::printf("train --data, 100 objects x 9 behaviours x 5 sessions, hold-out session: %.1f s\n",
              r.seconds);
  EXPECT_NE(r.out.find("shake: audio "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("haptic "), std::string::npos) << r.out;
  const pomdp::Problem p = pomdp::load_problem(problem.string());
  const auto& data = p.model->object_identification()->data();
  EXPECT_EQ(data.objects.size(), 100u);
  EXPECT_EQ(data.sorting.size(), 20u);
  EXPECT_EQ(data.sensing.size(), 9u);
  EXPECT_EQ(data.observation_table[0].size(), 100u);
  EXPECT_EQ(data.observation_table[0][0].size(), 100u);
  EXPECT_EQ(data.sorting_reward[0][0], 10.0);
  EXPECT_EQ(data.sorting_reward[0][5], -100.0);
  EXPECT_EQ(data.sensing[0].reward, -1.0);
}

TEST(TrainDatasetCli, HoldingOutObjectsRecognisesTheGroups) {
  const fs::path set = issue_scale_set();
  const fs::path problem =
      set.parent_path() / ("train_cli_obj_" + std::to_string(::getpid()) + ".yaml");
  const auto r =
      run("train --data '" + set.string() + "' --groups '" + (set / "groups.csv").string() +
          "' --hold-out object --feature-classifier nearest-neighbour --problem-out '" +
          problem.string() + "'");
  ASSERT_EQ(r.status, 0) << r.err;
  std::printf("train --data, hold-out object, nearest-neighbour: %.1f s\n", r.seconds);
  const pomdp::Problem p = pomdp::load_problem(problem.string());
  EXPECT_EQ(p.model->object_identification()->data().objects.size(), 20u);
}

TEST(TrainDatasetCli, BadInputExitsWithTwoAndSaysWhy) {
  const fs::path set = issue_scale_set();
  const std::string data = " --data '" + set.string() + "'";
  auto r = run("train" + data);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--problem-out"), std::string::npos) << r.err;
  r = run("train" + data + " --hold-out group --problem-out /tmp/x.yaml");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("session or object"), std::string::npos) << r.err;
  r = run("train" + data + " --hold-out object --problem-out /tmp/x.yaml");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("groups file"), std::string::npos) << r.err;
  const fs::path partial =
      set.parent_path() / ("partial_groups_" + std::to_string(::getpid()) + ".csv");
  std::ofstream(partial) << "object,group\nobj0,a\n";
  r = run("train" + data + " --groups '" + partial.string() + "' --problem-out /tmp/x.yaml");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("'obj1'"), std::string::npos) << r.err;
  r = run("train" + data + " --groups '" + partial.string() + "' --out model.json");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("'obj1'"), std::string::npos) << r.err;
  // Every option is open to every kind of data; a combination without meaning is named.
  r = run("train" + data + " --out /tmp/x.json --reject --table counts");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("the reject option needs one modality per action"), std::string::npos)
      << r.err;
  r = run("train" + data + " --out /tmp/x.json --cross-validation performance --temper");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("tempering fits how a session's repeats err together"), std::string::npos)
      << r.err;
  r = run("train" + data + " --out /tmp/x.json --cross-validation performance --table shrunk");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("turn the reject option off"), std::string::npos) << r.err;
  r = run("train" + data +
          " --problem-out /tmp/x.yaml --problem-base problems/audio_objects.yaml "
          "--reward-right 5");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--reward-right prices the data's own problem"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace echoplan
