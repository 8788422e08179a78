// ABT with the policy leaf value on the shipped seed problem: it decides from the tree's exact
// belief, which follows the real steps; POMCP refuses the policy leaf (it stays textbook).
#include "solvers/abt_solver.h"

#include <gtest/gtest.h>

#include <string>

#include "common/error.h"
#include "pomdp/exact_belief.h"
#include "pomdp/problem.h"
#include "solvers/pomcp_solver.h"

namespace echoplan::solvers {
namespace {

std::string repo_file(const std::string& relative) {
  return std::string(ECHOPLAN_SOURCE_DIR) + "/" + relative;
}

constexpr int kStrike = 1, kMoveToA = 2;

SearchOptions policy_leaf() {
  SearchOptions options;
  options.leaf.mode = LeafMode::policy;
  options.root_particles = 200;
  return options;
}

TEST(AbtPolicyLeaf, SensesFirstAndSortsOnceTheEvidenceIsStrong) {
  const pomdp::Problem p = pomdp::load_problem(repo_file("problems/audio_objects.yaml"));
  AbtSolver solver(p.model, policy_leaf());
  pomdp::ExactBelief belief(p.model);
  Rng rng(5);
  solver.reset(belief, rng);
  solver.improve(Budget::episodes(3000), rng);
  // At the uniform prior sorting loses 45 on average; V*(b0) is about 2.95.
  EXPECT_FALSE(solver.best_action() >= kMoveToA);
  // Five strikes that all sound like the pringles can (A): P(B) = 8e-6, so sorting to A is best by
  // far (sensing once more costs at least 1 and can gain at most 110 * 8e-6).
  pomdp::Observation pringles;
  pringles.index = 0;
  for (int i = 0; i < 5; ++i) {
    belief.update(kStrike, pringles, rng);
    solver.update(kStrike, pringles, belief, rng);
  }
  solver.improve(Budget::episodes(2000), rng);
  EXPECT_EQ(solver.best_action(), kMoveToA);
}

TEST(AbtPolicyLeaf, NeedsAnIdentificationProblem) {
  const pomdp::Problem tiger = pomdp::load_problem(repo_file("problems/tiger.pomdp"));
  EXPECT_THROW(AbtSolver(tiger.model, policy_leaf()), InputError);
  EXPECT_EQ(default_leaf_mode("abt", *tiger.model), LeafMode::lookahead);
  const pomdp::Problem seed = pomdp::load_problem(repo_file("problems/audio_objects.yaml"));
  EXPECT_EQ(default_leaf_mode("abt", *seed.model), LeafMode::policy);
  EXPECT_EQ(default_leaf_mode("pomcp", *seed.model), LeafMode::lookahead);
  EXPECT_THROW(PomcpSolver(seed.model, policy_leaf()), InputError);
}

}  // namespace
}  // namespace echoplan::solvers
