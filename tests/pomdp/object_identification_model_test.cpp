// ObjectIdentificationModel: the report's dynamics, rewards, sampled observations and its tables.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>

#include "pomdp/problem.h"
#include "test_paths.h"

namespace echoplan::pomdp {
namespace {

using testing::repo_file;

class ReportModel : public ::testing::Test {
 protected:
  Problem problem = load_problem(repo_file("problems/audio_objects.yaml"));
  const ObjectIdentificationModel& model = (*problem.model->object_identification());
  static constexpr int kSlide = 0, kStrike = 1, kMoveA = 2, kMoveB = 3;
};

TEST_F(ReportModel, InitialStateIsTheFixedConfiguration) {
  Rng rng(1);
  std::vector<int> counts(4, 0);
  const int n = 40000;
  for (int i = 0; i < n; ++i) {
    const State s = model.sample_initial_state(rng);
    ASSERT_EQ(s.continuous.size(), 10u);
    EXPECT_EQ(s.continuous[0], -2.89527);
    EXPECT_EQ(s.continuous[7], 0.1);
    ++counts[s.discrete[0]];
  }
  // Uniform over 4 objects: each count ~ Binomial(n, 1/4), sd = sqrt(n p (1-p)) ~ 87; allow 5 sd.
  for (int c : counts) EXPECT_NEAR(c, n / 4.0, 5 * std::sqrt(n * 0.25 * 0.75));
}

TEST_F(ReportModel, SlideMovesTheObjectStrikeLeavesIt) {
  Rng rng(2);
  const State s0 = model.sample_initial_state(rng);
  const StepResult slide = model.step(s0, kSlide, rng);
  EXPECT_DOUBLE_EQ(slide.next.continuous[7], 0.15);
  EXPECT_EQ(slide.next.continuous[8], 0.0);
  EXPECT_EQ(slide.next.discrete, s0.discrete);
  EXPECT_EQ(slide.reward, -1.0);
  EXPECT_FALSE(slide.terminal);
  const StepResult strike = model.step(slide.next, kStrike, rng);
  EXPECT_EQ(strike.next.continuous, slide.next.continuous);
  EXPECT_EQ(strike.reward, -1.0);
  EXPECT_FALSE(strike.terminal);
}

TEST_F(ReportModel, SortingRewardsFollowTheGroups) {
  Rng rng(3);
  State s = model.tabular_state(0);
  const double expect_a[4] = {10, -100, 10, -100};
  for (int k = 0; k < 4; ++k) {
    s.discrete[0] = k;
    const StepResult a = model.step(s, kMoveA, rng);
    const StepResult b = model.step(s, kMoveB, rng);
    EXPECT_EQ(a.reward, expect_a[k]);
    EXPECT_EQ(b.reward, -90 - expect_a[k]);
    EXPECT_TRUE(a.terminal);
    EXPECT_FALSE(a.collision);
    EXPECT_EQ(a.observation.index, model.none_symbol());
    // The heuristic is the value of sorting correctly now.
    EXPECT_EQ(model.heuristic_value(s), 10.0);
  }
}

// Sampled observations follow the table: chi-square-free check, each frequency within 5 binomial
// standard deviations of its probability.
TEST_F(ReportModel, SampledObservationsFollowTheTable) {
  Rng rng(4);
  const int n = 20000;
  for (int a : {kSlide, kStrike}) {
    for (int k = 0; k < 4; ++k) {
      State s = model.tabular_state(k);
      std::vector<int> counts(5, 0);
      for (int i = 0; i < n; ++i) ++counts[model.step(s, a, rng).observation.index];
      EXPECT_EQ(counts[4], 0);
      for (int o = 0; o < 4; ++o) {
        const double p = model.data().observation_table[a][k][o];
        EXPECT_NEAR(counts[o] / double(n), p, 5 * std::sqrt(p * (1 - p) / n) + 1e-12)
            << a << k << o;
        EXPECT_EQ(model.observation_likelihood(s, a, Observation{o, {}}), p);
      }
    }
  }
}

TEST_F(ReportModel, LikelihoodOfImpossibleObservationsIsZero) {
  const State s = model.tabular_state(1);
  EXPECT_EQ(model.observation_likelihood(s, kSlide, Observation{model.none_symbol(), {}}), 0.0);
  EXPECT_EQ(model.observation_likelihood(s, kSlide, Observation{99, {}}), 0.0);
  EXPECT_EQ(model.observation_likelihood(s, kSlide, Observation{-1, {}}), 0.0);
  EXPECT_EQ(model.observation_likelihood(s, kMoveA, Observation{model.none_symbol(), {}}), 1.0);
}

TEST_F(ReportModel, SpecNamesEverything) {
  const ModelSpec& spec = model.spec();
  EXPECT_EQ(spec.state.continuous_names.size(), 10u);
  EXPECT_EQ(spec.state.discrete_value_names[0].size(), 4u);
  EXPECT_EQ(spec.observation.names.back(), "none");
  EXPECT_EQ(spec.min_reward, -100.0);
  EXPECT_EQ(spec.max_reward, 10.0);
  EXPECT_EQ(spec.discount, 0.99);
}

// The tabular view agrees with what the generative step does.
TEST_F(ReportModel, TabularViewMatchesTheStep) {
  const TabularModel& t = *model.tabular();
  ASSERT_EQ(t.num_states(), 5);
  ASSERT_EQ(t.num_observations(), 5);
  EXPECT_TRUE(t.terminal(4));
  EXPECT_FALSE(t.terminal(0));
  Rng rng(5);
  for (int k = 0; k < 4; ++k) {
    for (int a = 0; a < 4; ++a) {
      const StepResult r = model.step(model.tabular_state(k), a, rng);
      EXPECT_EQ(t.reward(k, a), r.reward);
      const int tabular_next = r.terminal ? 4 : r.next.discrete[0];
      EXPECT_EQ(t.transition(k, a, tabular_next), 1.0);
      EXPECT_GT(t.observation(a, tabular_next, r.observation.index), 0.0);
    }
  }
  for (int a = 0; a < 4; ++a) {
    EXPECT_EQ(t.transition(4, a, 4), 1.0);
    EXPECT_EQ(t.reward(4, a), 0.0);
  }
}

TEST(ObjectModelCollision, CollisionEndsWithItsReward) {
  std::ifstream in(repo_file("problems/audio_objects.yaml"));
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  text.replace(text.find("    slide: 0\n"), 13, "    slide: 0.25\n");
  const Problem p = parse_problem_yaml(text, "collide.yaml");
  const auto& m = (*p.model->object_identification());
  Rng rng(6);
  const int n = 20000;
  int collisions = 0;
  for (int i = 0; i < n; ++i) {
    const StepResult r = m.step(m.tabular_state(0), 0, rng);
    if (r.collision) {
      ++collisions;
      EXPECT_TRUE(r.terminal);
      EXPECT_EQ(r.reward, -100.0);
      EXPECT_EQ(r.next.continuous[7], 0.1);  // the push did not happen
    }
  }
  // Binomial(n, 0.25): 5 sd.
  EXPECT_NEAR(collisions / double(n), 0.25, 5 * std::sqrt(0.25 * 0.75 / n));
  const TabularModel& t = *m.tabular();
  EXPECT_DOUBLE_EQ(t.reward(0, 0), 0.75 * -1 + 0.25 * -100);
  EXPECT_EQ(t.transition(0, 0, 4), 0.25);
  EXPECT_EQ(t.transition(0, 0, 0), 0.75);
  EXPECT_EQ(m.spec().min_reward, -100.0);
}

}  // namespace
}  // namespace echoplan::pomdp
