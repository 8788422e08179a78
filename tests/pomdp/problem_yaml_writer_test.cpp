// write_problem_yaml() writes what parse_problem_yaml() reads back to the same problem.
#include <gtest/gtest.h>

#include <sstream>

#include "pomdp/problem.h"
#include "test_paths.h"

namespace echoplan::pomdp {
namespace {

using testing::repo_file;

const ObjectIdentificationModel& object_model(const Problem& p) {
  return (*p.model->object_identification());
}

TEST(ProblemYamlWriter, WrittenProblemReadsBackIdentically) {
  const Problem p = load_problem(repo_file("problems/audio_objects.yaml"));
  std::ostringstream out;
  write_problem_yaml(out, object_model(p).data(), p.belief, p.planner);
  const Problem q = parse_problem_yaml(out.str(), "written.yaml");
  const ObjectProblemData& a = object_model(p).data();
  const ObjectProblemData& b = object_model(q).data();
  EXPECT_EQ(a.objects, b.objects);
  EXPECT_EQ(a.prior, b.prior);
  EXPECT_EQ(a.observation_table, b.observation_table);
  EXPECT_EQ(a.sorting_reward, b.sorting_reward);
  EXPECT_EQ(a.initial_joints, b.initial_joints);
  EXPECT_EQ(q.planner.step_ms, p.planner.step_ms);
  EXPECT_EQ(q.planner.exploration, p.planner.exploration);
}

// A problem without limits writes no `uses:` at all (the writer's output for such problems is what
// it was before limits existed); one with limits writes them and reads them back.
TEST(ProblemYamlWriter, UseLimitsAreWrittenOnlyWhenSetAndReadBack) {
  const Problem p = load_problem(repo_file("problems/audio_objects.yaml"));
  std::ostringstream plain;
  write_problem_yaml(plain, object_model(p).data(), p.belief, p.planner);
  EXPECT_EQ(plain.str().find("uses"), std::string::npos);

  ObjectProblemData d = object_model(p).data();
  d.sensing[1].uses = 2;
  std::ostringstream limited;
  write_problem_yaml(limited, d, p.belief, p.planner);
  EXPECT_NE(limited.str().find("  uses:\n    strike: 2\n"), std::string::npos) << limited.str();
  const Problem q = parse_problem_yaml(limited.str(), "written.yaml");
  EXPECT_EQ(object_model(q).data().sensing[0].uses, 0);
  EXPECT_EQ(object_model(q).data().sensing[1].uses, 2);
  // Written again, the text is the same.
  std::ostringstream again;
  write_problem_yaml(again, object_model(q).data(), q.belief, q.planner);
  EXPECT_EQ(again.str(), limited.str());
}

TEST(ProblemYamlWriter, PrerequisitesAreWrittenOnlyWhenSetAndReadBack) {
  const Problem p = load_problem(repo_file("problems/grasp_first.yaml"));
  EXPECT_EQ(object_model(p).data().sensing[2].prerequisites, (std::vector<int>{1}));
  std::ostringstream out;
  write_problem_yaml(out, object_model(p).data(), p.belief, p.planner);
  EXPECT_NE(out.str().find("  requires:\n    shake: [grasp]\n"), std::string::npos) << out.str();
  const Problem q = parse_problem_yaml(out.str(), "written.yaml");
  EXPECT_EQ(q.model->prerequisites(2), (std::vector<int>{1}));
  EXPECT_TRUE(q.model->prerequisites(0).empty());
  ObjectProblemData plain = object_model(p).data();
  plain.sensing[2].prerequisites.clear();
  std::ostringstream none;
  write_problem_yaml(none, plain, p.belief, p.planner);
  EXPECT_EQ(none.str().find("requires"), std::string::npos);
}

// Numbers with no short decimal form (1/3, 0.1 + 0.2) and the settings the report's problem file
// does not use (exact belief, an episode budget) survive the round trip bit for bit.
TEST(ProblemYamlWriter, EveryDoubleAndSettingRoundTripsExactly) {
  ObjectProblemData d = object_model(load_problem(repo_file("problems/audio_objects.yaml"))).data();
  d.observation_table[0][0] = {1.0 / 3.0, 1.0 / 3.0, 1.0 / 6.0, 1.0 / 6.0};
  d.prior = {0.1 + 0.2, 0.7 - 0.2, 0.1, 0.1};
  d.sensing[1].collision_probability = 1e-7;
  d.collision_reward = -123.456789012345;
  BeliefSettings belief;
  belief.type = BeliefSettings::Type::exact;
  belief.particles = 7;
  PlannerDefaults planner;
  planner.solver = "pomcp";
  planner.episodes = 321;
  planner.step_ms = 0.0;
  planner.depth = 17;
  planner.exploration = 2.0 / 3.0;
  std::ostringstream out;
  write_problem_yaml(out, d, belief, planner);

  const Problem q = parse_problem_yaml(out.str(), "written.yaml");
  const ObjectProblemData& b = object_model(q).data();
  EXPECT_EQ(b.observation_table, d.observation_table);
  EXPECT_EQ(b.sensing[1].collision_probability, 1e-7);
  EXPECT_EQ(b.collision_reward, d.collision_reward);
  // The reader normalises the prior; these weights already sum to 1 up to one rounding.
  for (std::size_t k = 0; k < d.prior.size(); ++k) EXPECT_NEAR(b.prior[k], d.prior[k], 1e-15);
  EXPECT_EQ(q.belief.type, BeliefSettings::Type::exact);
  EXPECT_EQ(q.belief.particles, 7);
  EXPECT_EQ(q.planner.solver, "pomcp");
  EXPECT_EQ(q.planner.episodes, 321);
  EXPECT_EQ(q.planner.step_ms, 0.0);
  EXPECT_EQ(q.planner.depth, 17);
  EXPECT_EQ(q.planner.exploration, 2.0 / 3.0);
}

}  // namespace
}  // namespace echoplan::pomdp
