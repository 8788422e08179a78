// The model as the world: it steps the true state until the episode ends.
#include "pomdp/model_environment.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "pomdp/problem.h"
#include "test_paths.h"

namespace echoplan::pomdp {
namespace {

using testing::repo_file;

constexpr int kSlide = 0, kStrike = 1;

TEST(ModelEnvironment, StepsTheTrueStateUntilTheEpisodeEnds) {
  const Problem p = load_problem(repo_file("problems/audio_objects.yaml"));
  const auto& m = (*p.model->object_identification());
  ModelEnvironment env(p.model);
  Rng rng(11);
  env.reset(m.tabular_state(2), rng);
  Outcome slide = env.execute(kSlide, rng);
  EXPECT_EQ(slide.reward, -1.0);
  EXPECT_FALSE(slide.terminal);
  EXPECT_NEAR(env.true_state().continuous[7], 0.15, 1e-12);
  Outcome sort = env.execute(2, rng);  // move_to_A: plastic_cup belongs at A
  EXPECT_EQ(sort.reward, 10.0);
  EXPECT_TRUE(sort.terminal);
  EXPECT_THROW(env.execute(kSlide, rng), std::logic_error);
}

TEST(ModelEnvironment, RefusesToStepBeforeResetOrWithAnUnknownAction) {
  const Problem p = load_problem(repo_file("problems/tiger.pomdp"));
  ModelEnvironment env(p.model);
  Rng rng(12);
  EXPECT_THROW(env.execute(0, rng), std::logic_error);
  env.reset(State{{}, {0}}, rng);
  EXPECT_THROW(env.execute(3, rng), std::out_of_range);
  EXPECT_THROW(env.execute(-1, rng), std::out_of_range);
  // Listening to the tiger on the left: -1, the tiger stays, the episode goes on.
  const Outcome listen = env.execute(0, rng);
  EXPECT_EQ(listen.reward, -1.0);
  EXPECT_FALSE(listen.terminal);
  EXPECT_EQ(env.true_state().discrete, (std::vector<int>{0}));
}

}  // namespace
}  // namespace echoplan::pomdp
