// The problem checker finds each kind of likely mistake, and nothing in the shipped problems.
#include "pomdp/problem_check.h"

#include <gtest/gtest.h>

#include "pomdp/cassandra_reader.h"
#include "test_paths.h"

namespace echoplan::pomdp {
namespace {

using testing::repo_file;

bool mentions(const std::vector<std::string>& findings, const std::string& part) {
  for (const auto& f : findings) {
    if (f.find(part) != std::string::npos) return true;
  }
  return false;
}

TEST(ProblemCheck, ShippedProblemsAreClean) {
  for (const char* file :
       {"problems/audio_objects.yaml", "problems/audio_objects.pomdp", "problems/tiger.pomdp"}) {
    EXPECT_EQ(check_problem(load_problem(repo_file(file))), std::vector<std::string>{}) << file;
  }
}

TEST(ProblemCheck, ObjectProblemMistakes) {
  Problem p = load_problem(repo_file("problems/audio_objects.yaml"));
  ObjectProblemData d = (*p.model->object_identification()).data();
  // Make coffee_mug sound like pringles_can under every action: they belong in different places.
  d.observation_table[0][1] = d.observation_table[0][0];
  d.observation_table[1][1] = d.observation_table[1][0];
  d.prior = {0.5, 0.5, 0.0, 0.0};
  d.sorting_reward[0][3] = -100;
  d.sorting_reward[1][3] = -100;
  p.model = std::make_shared<const ObjectIdentificationModel>(d);
  const std::vector<std::string> findings = check_problem(p);
  EXPECT_TRUE(mentions(findings, "'pringles_can' and 'coffee_mug' sound the same"));
  EXPECT_TRUE(mentions(findings, "object 'plastic_cup' has prior 0"));
  EXPECT_TRUE(mentions(findings, "worst outcome for object 'paper_base'"));
  // Zero prior also makes those states unreachable in the tables.
  EXPECT_TRUE(mentions(findings, "state 'plastic_cup' cannot be reached"));
}

TEST(ProblemCheck, TableMistakes) {
  Problem p;
  p.model = parse_cassandra_pomdp(R"(
discount: 0.9
states: a b end
actions: look wait
observations: x y never
start: 0.5 0.25 0.25
T: look identity
T: wait identity
O: look
0.5 0.5 0
0.5 0.5 0
0 1 0
O: wait : * : x 1.0
R: look : a : * : * -1
R: look : b : * : * -1
R: wait : a : * : * -1
R: wait : b : * : * -1
)",
                                  "mistakes.pomdp");
  const std::vector<std::string> findings = check_problem(p);
  EXPECT_TRUE(mentions(findings, "action 'look' never changes the state"));
  EXPECT_TRUE(mentions(findings, "terminal state 'end'"));
  EXPECT_TRUE(mentions(findings, "observation 'never' can never occur"));
  EXPECT_FALSE(mentions(findings, "observation 'y' can never occur"));
}

}  // namespace
}  // namespace echoplan::pomdp
