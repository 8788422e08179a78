#include "solvers/observation_branch.h"

#include <gtest/gtest.h>

namespace echoplan::solvers {
namespace {

TEST(ObservationBranching, DiscreteObservationsBranchBySymbol) {
  const ObservationBranching branching{0.5};  // the threshold must not matter for symbols
  pomdp::Observation a, b;
  a.index = 2;
  b.index = 2;
  EXPECT_TRUE(branching.same_branch(a, b));
  b.index = 3;
  EXPECT_FALSE(branching.same_branch(a, b));
}

TEST(ObservationBranching, ContinuousObservationsBranchByEuclideanDistance) {
  const ObservationBranching branching{1.0};
  pomdp::Observation centre, near, far;
  centre.values = {0.0, 0.0};
  near.values = {0.6, 0.8};  // distance exactly 1.0: inside (the threshold is inclusive)
  far.values = {0.6, 0.81};  // just beyond
  EXPECT_TRUE(branching.same_branch(centre, near));
  EXPECT_FALSE(branching.same_branch(centre, far));
  pomdp::Observation other_dimension;
  other_dimension.values = {0.0};
  EXPECT_FALSE(branching.same_branch(centre, other_dimension));
}

}  // namespace
}  // namespace echoplan::solvers
