// save_policy / load_policy on the shipped tiger problem (problems/tiger.pomdp): what the file
// holds, an exact round trip of every vector, and the rejections not covered by policy_test.cpp
// (which checks the report's problem's round trip through the trials solver and the JSON syntax,
// size, action and value checks): the format and version fields, the root and entries that are not
// objects, a truncated file, a file that cannot be written.
#include "solvers/offline/policy_file.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "../../common/source_dir.h"
#include "common/error.h"
#include "pomdp/problem.h"

namespace echoplan::solvers::offline {
namespace {

std::shared_ptr<const FlatPomdp> tiger() {
  const pomdp::Problem p =
      pomdp::load_problem(echoplan::testing::source_dir() + "/problems/tiger.pomdp");
  return std::make_shared<const FlatPomdp>(make_flat_pomdp(*p.model->tabular()));
}

// A temporary file path unique to this test binary, removed when the object goes.
struct TempFile {
  explicit TempFile(const std::string& name)
      : path((std::filesystem::temp_directory_path() / ("echoplan_policy_file_test_" + name))
                 .string()) {}
  ~TempFile() { std::filesystem::remove(path); }
  std::string path;
};

// A tiger policy from a fixed amount of solver work (the same vectors on every machine).
std::unique_ptr<PointBasedSolver> solved_tiger() {
  SolverOptions options;
  options.max_trials = 50;
  auto solver = std::make_unique<PointBasedSolver>(tiger(), options);
  solver->solve();
  return solver;
}

TEST(PolicyFile, RoundTripKeepsEveryVectorExactly) {
  const auto solver = solved_tiger();
  TempFile file("round_trip.json");
  save_policy(*solver, file.path);
  const AlphaVectorSet loaded = load_policy(file.path, solver->pomdp());
  const auto& saved = solver->lower_bound().vectors();
  ASSERT_GT(saved.size(), 1u) << "50 trials should leave more than the initial vector";
  ASSERT_EQ(loaded.size(), saved.size());
  for (std::size_t i = 0; i < saved.size(); ++i) {
    EXPECT_EQ(loaded.vectors()[i].action, saved[i].action) << i;
    EXPECT_EQ(loaded.vectors()[i].values, saved[i].values) << i;  // bit for bit
  }
}

TEST(PolicyFile, FileRecordsTheProblemSizesAndBounds) {
  const auto solver = solved_tiger();
  TempFile file("contents.json");
  save_policy(*solver, file.path);
  std::ifstream in(file.path);
  const nlohmann::json j = nlohmann::json::parse(in);
  EXPECT_EQ(j.at("format"), "echoplan-alpha-vectors");
  EXPECT_EQ(j.at("version"), 1);
  // tiger.pomdp: 2 states, 3 actions, discount 0.95.
  EXPECT_EQ(j.at("num_states"), 2);
  EXPECT_EQ(j.at("num_actions"), 3);
  EXPECT_EQ(j.at("discount").get<double>(), 0.95);
  EXPECT_EQ(j.at("lower").get<double>(), solver->progress().root.lower);
  EXPECT_EQ(j.at("upper").get<double>(), solver->progress().root.upper);
  // The tiger's known V*(uniform) = 19.371 lies between the recorded bounds.
  EXPECT_LE(j.at("lower").get<double>(), 19.372);
  EXPECT_GE(j.at("upper").get<double>(), 19.371);
  EXPECT_EQ(j.at("vectors").size(), solver->lower_bound().size());
}

// Writes `text` to a file and expects load_policy on tiger to reject it naming that file, `line`
// and a problem containing `fragment`.
void expect_rejected(const std::string& text, int line, const std::string& fragment) {
  // Named after the test: ctest may run this binary's tests in parallel processes.
  TempFile file(std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) +
                ".json");
  std::ofstream(file.path) << text;
  try {
    load_policy(file.path, *tiger());
    ADD_FAILURE() << "accepted: " << text;
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), file.path);
    EXPECT_EQ(e.line(), line) << e.what();
    EXPECT_NE(e.problem().find(fragment), std::string::npos) << e.what();
  }
}

const std::string kTigerHead =
    R"({"format": "echoplan-alpha-vectors", "version": 1, "num_states": 2, "num_actions": 3,
          "discount": 0.95, )";

TEST(PolicyFile, RejectsAnotherFormatOrVersion) {
  expect_rejected(R"({"format": "pomdpx-policy", "version": 1})", 0,
                  "\"format\" must be \"echoplan-alpha-vectors\"");
  expect_rejected(R"({"format": 7, "version": 1})", 0, "\"format\" must be");
  expect_rejected(R"({"format": "echoplan-alpha-vectors", "version": 2})", 0,
                  "unsupported version (this echoplan reads 1)");
  expect_rejected(R"({"format": "echoplan-alpha-vectors", "version": "1"})", 0,
                  "\"version\" must be an integer");
  expect_rejected(R"({"format": "echoplan-alpha-vectors", "version": 1.5})", 0,
                  "\"version\" must be an integer");
}

TEST(PolicyFile, RejectsWrongShapes) {
  expect_rejected("[1, 2, 3]", 0, "missing key \"format\"");
  expect_rejected(kTigerHead + R"("vectors": {"action": 0}})", 0, "non-empty array");
  expect_rejected(kTigerHead + R"("vectors": [[0, 1, 2]]})", 0, "vectors[0] must be an object");
  expect_rejected(
      kTigerHead + R"("vectors": [{"action": 0, "values": [1, 2]}, {"values": [1, 2]}]})", 0,
      "missing key \"action\"");
  expect_rejected(kTigerHead + R"("vectors": [{"action": -1, "values": [1, 2]}]})", 0,
                  "vectors[0].action -1 is not in [0, 3)");
  // The same states but another action count is another problem.
  expect_rejected(R"({"format": "echoplan-alpha-vectors", "version": 1, "num_states": 2,
                     "num_actions": 4, "vectors": []})",
                  0, "the policy is for 2 states and 4 actions, the problem has 2 and 3");
}

TEST(PolicyFile, RejectsAPolicySolvedAtAnotherDiscount) {
  // tiger.pomdp has discount 0.95; the same vectors at 0.99 value another horizon.
  const std::string sizes =
      R"({"format": "echoplan-alpha-vectors", "version": 1, "num_states": 2, "num_actions": 3, )";
  const std::string vectors = R"("vectors": [{"action": 0, "values": [1, 2]}]})";
  expect_rejected(sizes + R"("discount": 0.99, )" + vectors, 0,
                  "the policy was solved at discount 0.99, the problem has 0.95");
  expect_rejected(sizes + R"("discount": "0.95", )" + vectors, 0, "\"discount\" must be a number");
  expect_rejected(sizes + vectors, 0, "missing key \"discount\"");
}

TEST(PolicyFile, RejectsNumbersOutOfRange) {
  // 2^32 + 2 would wrap to 2 states in an int.
  expect_rejected(R"({"format": "echoplan-alpha-vectors", "version": 4294967297})", 0,
                  "\"version\" must be an integer");
  expect_rejected(kTigerHead + R"("vectors": [{"action": 0, "values": [1e400, 2]}]})", 0,
                  "a number is out of range");
}

TEST(PolicyFile, TruncatedFileNamesTheLineWhereItEnds) {
  // kTigerHead spans two lines; the file ends on line 5.
  expect_rejected(kTigerHead + "\n\"vectors\": [\n{\"action\": 0,\n", 5, "not valid JSON");
  expect_rejected("", 1, "not valid JSON");
}

// 100,000 nested arrays (200 KB): refused at the parse (common/json_parse.h), before the reader
// sees a value that would overflow the stack if it were copied.
TEST(PolicyFile, RejectsDeepNesting) {
  expect_rejected(
      kTigerHead + R"("vectors": )" + std::string(100'000, '[') + std::string(100'000, ']') + "}",
      0, "nested deeper than");
}

TEST(PolicyFile, UnwritablePathIsAnInputErrorNamingIt) {
  const auto solver = solved_tiger();
  const std::string path = "/nonexistent-echoplan-dir/policy.json";
  try {
    save_policy(*solver, path);
    ADD_FAILURE() << "wrote " << path;
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), path);
    EXPECT_NE(e.problem().find("cannot write"), std::string::npos) << e.what();
  }
}

TEST(PolicyFile, MissingFileNamesIt) {
  const std::string path = "/nonexistent-echoplan-dir/policy.json";
  try {
    load_policy(path, *tiger());
    ADD_FAILURE() << "loaded " << path;
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), path);
    EXPECT_NE(e.problem().find("cannot open"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace echoplan::solvers::offline
