// make_belief() builds the belief a problem file asks for.
#include "pomdp/make_belief.h"

#include <gtest/gtest.h>

#include <cmath>
#include <typeinfo>

#include "pomdp/exact_belief.h"
#include "pomdp/particle_belief.h"
#include "pomdp/problem.h"
#include "test_paths.h"

namespace echoplan::pomdp {
namespace {

using testing::repo_file;

constexpr int kSlide = 0, kStrike = 1;

TEST(MakeBelief, FollowsTheProblemSettings) {
  Problem p = load_problem(repo_file("problems/audio_objects.yaml"));
  Rng rng(10);
  BeliefPtr particles = make_belief(p, rng);
  ASSERT_EQ(typeid(*particles), typeid(ParticleBelief));
  EXPECT_EQ(static_cast<ParticleBelief&>(*particles).size(), 1000);
  p.belief.type = BeliefSettings::Type::exact;
  BeliefPtr exact = make_belief(p, rng);
  EXPECT_EQ(typeid(*exact), typeid(ExactBelief));
  // A clone is independent of its original.
  BeliefPtr copy = exact->clone();
  exact->update(kStrike, Observation{0, {}}, rng);
  EXPECT_EQ(copy->discrete_marginal(0), (std::vector<double>{0.25, 0.25, 0.25, 0.25}));
}

}  // namespace
}  // namespace echoplan::pomdp
