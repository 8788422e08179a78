// Random problems: valid, reproducible from the seed, shaped as asked, and they round-trip
// through the YAML writer and loader.
#include "pomdp/random_problem.h"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "pomdp/problem.h"

namespace echoplan::pomdp {
namespace {

ObjectProblemData make(int objects, int actions, std::uint64_t seed, double concentration = 1.5) {
  Rng rng(seed);
  return make_random_object_problem(RandomProblemSettings{objects, actions, concentration, seed},
                                    rng);
}

TEST(RandomProblem, ShapeValidityAndGroups) {
  const ObjectProblemData d = make(16, 4, 1);
  EXPECT_NO_THROW(validate_object_problem(d));
  ASSERT_EQ(d.objects.size(), 16u);
  ASSERT_EQ(d.sensing.size(), 4u);
  EXPECT_EQ(d.objects.front(), "object_01");
  int at_a = 0;
  for (int k = 0; k < 16; ++k) {
    at_a += d.sorting_reward[0][k] == 10.0 ? 1 : 0;
    EXPECT_EQ(d.sorting_reward[0][k] + d.sorting_reward[1][k], -90.0);
  }
  EXPECT_EQ(at_a, 8);
}

// The expected diagonal is C/(C+1); over 4 x 64 rows the mean's standard deviation is below
// 0.01 (each Beta(C(K-1), K-1) entry has sd < 0.06), so 0.03 is a 3-sd band.
TEST(RandomProblem, DiagonalMassFollowsTheConcentration) {
  for (double c : {1.5, 4.0}) {
    const ObjectProblemData d = make(64, 4, 2, c);
    double sum = 0.0;
    int rows = 0;
    for (const auto& block : d.observation_table) {
      for (std::size_t k = 0; k < block.size(); ++k) {
        sum += block[k][k];
        ++rows;
        for (double p : block[k]) EXPECT_GE(p, 1e-4);
      }
    }
    EXPECT_NEAR(sum / rows, c / (c + 1), 0.03) << c;
  }
}

TEST(RandomProblem, SameSeedSameProblemOtherSeedOtherProblem) {
  EXPECT_EQ(make(16, 4, 3).observation_table, make(16, 4, 3).observation_table);
  EXPECT_NE(make(16, 4, 3).observation_table, make(16, 4, 4).observation_table);
}

TEST(RandomProblem, RoundTripsThroughYaml) {
  const ObjectProblemData d = make(16, 4, 5);
  PlannerDefaults planner;
  planner.episodes = 1000;
  planner.step_ms = 0;
  std::ostringstream out;
  write_problem_yaml(out, d, BeliefSettings{BeliefSettings::Type::exact, 500}, planner);
  const Problem p = parse_problem_yaml(out.str(), "random.yaml");
  const auto& back = (*p.model->object_identification()).data();
  EXPECT_EQ(back.name, d.name);
  EXPECT_EQ(back.objects, d.objects);
  EXPECT_EQ(back.prior, d.prior);
  EXPECT_EQ(back.observation_table, d.observation_table);
  EXPECT_EQ(back.sorting_reward, d.sorting_reward);
  EXPECT_EQ(back.sensing[2].name, d.sensing[2].name);
  EXPECT_EQ(p.belief.type, BeliefSettings::Type::exact);
  EXPECT_EQ(p.belief.particles, 500);
  EXPECT_EQ(p.planner.episodes, 1000);
  EXPECT_EQ(p.planner.step_ms, 0.0);
}

TEST(RandomProblem, RejectsBadSettings) {
  Rng rng(1);
  EXPECT_THROW(make_random_object_problem({1, 4, 1.5, 1}, rng), std::invalid_argument);
  EXPECT_THROW(make_random_object_problem({4, 0, 1.5, 1}, rng), std::invalid_argument);
  EXPECT_THROW(make_random_object_problem({4, 2, 0.0, 1}, rng), std::invalid_argument);
}

}  // namespace
}  // namespace echoplan::pomdp
