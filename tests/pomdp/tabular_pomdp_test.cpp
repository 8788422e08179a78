// TabularPomdp as a generative model: sampled steps follow its tables; the heuristic is the MDP
// value.
#include "pomdp/tabular_pomdp.h"

#include <gtest/gtest.h>

#include <cmath>

#include "pomdp/problem.h"
#include "test_paths.h"

namespace echoplan::pomdp {
namespace {

using testing::repo_file;

TEST(TabularPomdp, SampledStepsFollowTheTables) {
  const Problem p = load_problem(repo_file("problems/tiger.pomdp"));
  Rng rng(1);
  const int n = 40000;
  int heard_left = 0, stayed = 0, reset_left = 0;
  for (int i = 0; i < n; ++i) {
    const StepResult listen = p.model->step(State{{}, {0}}, 0, rng);
    EXPECT_EQ(listen.reward, -1.0);
    stayed += listen.next.discrete[0] == 0 ? 1 : 0;
    heard_left += listen.observation.index == 0 ? 1 : 0;
    const StepResult open = p.model->step(State{{}, {0}}, 2, rng);
    EXPECT_EQ(open.reward, 10.0);
    EXPECT_FALSE(open.terminal);
    reset_left += open.next.discrete[0] == 0 ? 1 : 0;
  }
  EXPECT_EQ(stayed, n);
  // Binomial proportions, 5 standard deviations.
  EXPECT_NEAR(heard_left / double(n), 0.85, 5 * std::sqrt(0.85 * 0.15 / n));
  EXPECT_NEAR(reset_left / double(n), 0.5, 5 * std::sqrt(0.25 / n));
}

// Tiger with the tiger's side known: open the other door every step, 10 / (1 - 0.95) = 200.
TEST(TabularPomdp, HeuristicIsTheMdpValue) {
  const Problem p = load_problem(repo_file("problems/tiger.pomdp"));
  // Value iteration stops within 1e-6 of the fixed point.
  EXPECT_NEAR(p.model->heuristic_value(State{{}, {0}}), 200.0, 1e-6);
  EXPECT_NEAR(p.model->heuristic_value(State{{}, {1}}), 200.0, 1e-6);
  // The report's problem as .pomdp: sorting right now (+10) is the known-object value; 'done' is
  // worth 0.
  const Problem objects = load_problem(repo_file("problems/audio_objects.pomdp"));
  EXPECT_NEAR(objects.model->heuristic_value(State{{}, {1}}), 10.0, 1e-6);
  EXPECT_EQ(objects.model->heuristic_value(State{{}, {4}}), 0.0);
  // Sorting reaches the absorbing state, which ends the episode.
  Rng rng(2);
  const StepResult sort = objects.model->step(State{{}, {1}}, 3, rng);
  EXPECT_TRUE(sort.terminal);
  EXPECT_EQ(sort.reward, 10.0);
  EXPECT_EQ(sort.next.discrete[0], 4);
}

TEST(TabularPomdp, RejectsInconsistentTables) {
  TabularPomdpData d;
  d.state_names = {"a"};
  d.action_names = {"x"};
  d.observation_names = {"o"};
  d.transition = {0.5};
  d.observation = {1.0};
  d.reward = {0.0};
  d.start = {1.0};
  EXPECT_THROW(TabularPomdp{d}, std::invalid_argument);
  d.transition = {1.0};
  d.discount = 1.0;
  EXPECT_THROW(TabularPomdp{d}, std::invalid_argument);
  d.discount = 0.9;
  EXPECT_NO_THROW(TabularPomdp{d});
}

}  // namespace
}  // namespace echoplan::pomdp
