// The partition relaxation's upper bound on V*: never below V* (against an independent
// brute-force search and against the exact solver run without it), nearly exact on two-state
// beliefs (its sub-problems), and tighter than "one more sensing reveals the state".
#include "solvers/pair_relaxation_bound.h"

#include <gtest/gtest.h>

#include <vector>

#include "../common/source_dir.h"
#include "identification_brute_force.h"
#include "pomdp/object_identification_model.h"
#include "pomdp/problem.h"
#include "solvers/identification_solver.h"

namespace echoplan::solvers {
namespace {

pomdp::ObjectProblemData report_data(double discount) {
  const pomdp::Problem p =
      pomdp::load_problem(echoplan::testing::source_dir() + "/problems/audio_objects.yaml");
  auto d = p.model->object_identification()->data();
  d.discount = discount;
  return d;
}

// The live part of a node's belief (the report's live states are its objects, in order).
std::vector<double> live_belief(const IdentificationSolver& solver, IdentificationSolver::NodeId n,
                                int objects) {
  std::vector<double> b = solver.belief(n);
  b.resize(objects);
  return b;
}

TEST(PairRelaxationBound, SolvesOnlyPairsThatMustBeToldApart) {
  // The report sorts {pringles_can, plastic_cup} to A and {coffee_mug, paper_base} to B: a pair in
  // one bin is worth its known values at once, so only the four pairs across bins need solving.
  const pomdp::ObjectIdentificationModel model(report_data(0.99));
  const IdentificationSolver solver(*model.tabular());
  const PairRelaxationBound& bound = solver.pair_relaxation();
  ASSERT_EQ(bound.num_pairs(), 4u);
  for (std::size_t x = 0; x < bound.num_pairs(); ++x) {
    const int i = bound.first_state(x), j = bound.second_state(x);
    const bool i_in_a = i == 0 || i == 2, j_in_a = j == 0 || j == 2;
    EXPECT_NE(i_in_a, j_in_a) << i << ", " << j;
    // At the ends the state is known (+10 for sorting it right).
    EXPECT_NEAR(bound.pair_value(x, 0.0), 10.0, 1e-12);
    EXPECT_NEAR(bound.pair_value(x, 1.0), 10.0, 1e-12);
  }
  IdentificationOptions off;
  off.pair_upper_bound = false;
  EXPECT_EQ(IdentificationSolver(*model.tabular(), off).num_relaxation_pairs(), 0u);
}

TEST(PairRelaxationBound, IsNearlyExactOnTwoStateBeliefs) {
  // A prior on two objects from different bins makes the problem the sub-problem itself: V* from
  // the exact solver run without the relaxation (to a gap of 1e-6) must lie below the bound, and
  // the bound within 2e-3 of it (the grid's resolution).
  const std::vector<std::pair<int, int>> pairs{{0, 1}, {2, 3}, {0, 3}};
  for (const auto& [i, j] : pairs) {
    for (double p : {0.5, 0.9, 0.03}) {
      auto d = report_data(0.95);
      d.prior.assign(4, 0.0);
      d.prior[i] = p;
      d.prior[j] = 1.0 - p;
      const pomdp::ObjectIdentificationModel model(d);
      IdentificationOptions off;
      off.pair_upper_bound = false;
      IdentificationSolver exact(*model.tabular(), off);
      RefineLimits limits;
      limits.target_gap = 1e-6;
      limits.expansions = 200000;
      ASSERT_TRUE(exact.refine(exact.root(), limits)) << i << "," << j << " p " << p;
      const Bounds v = exact.value(exact.root());
      const IdentificationSolver with_pairs(*model.tabular());
      const double bound =
          with_pairs.pair_relaxation().value(live_belief(with_pairs, with_pairs.root(), 4).data());
      EXPECT_GE(bound, v.lower - 1e-9) << i << "," << j << " p " << p;
      EXPECT_LE(bound, v.upper + 2e-3) << i << "," << j << " p " << p;
    }
  }
}

TEST(PairRelaxationBound, BoundsVStarFromAboveAndBeatsOneMoreSensingAlongHistories) {
  // At the start and after histories that leave two, three or four objects in doubt: the bound
  // is at least the brute-force lower bound and the exact solver's lower bound (both plans that
  // can be carried out), and below the one-more-sensing bound a fresh node starts with when
  // the relaxation is off.
  const pomdp::ObjectIdentificationModel model(report_data(0.95));
  const pomdp::TabularModel& m = *model.tabular();
  IdentificationOptions off;
  off.pair_upper_bound = false;
  IdentificationSolver with_pairs(m), without(m, off), fresh(m, off);
  testing::BruteForceValue brute_force(m, 6);
  const std::vector<std::vector<std::pair<int, int>>> histories{
      {}, {{1, 2}}, {{0, 3}, {1, 3}}, {{1, 0}, {1, 1}}, {{0, 2}, {0, 2}, {1, 3}}, {{1, 2}, {1, 0}}};
  RefineLimits limits;
  limits.target_gap = 1e-5;
  limits.expansions = 20000;
  for (const auto& history : histories) {
    auto a = with_pairs.root(), b = without.root(), c = fresh.root();
    for (const auto& [action, observation] : history) {
      a = with_pairs.child(a, action, observation);
      b = without.child(b, action, observation);
      c = fresh.child(c, action, observation);
    }
    const std::vector<double> belief = live_belief(with_pairs, a, 4);
    const double bound = with_pairs.pair_relaxation().value(belief.data());
    const Bounds reference = brute_force.value(with_pairs.belief(a));
    without.refine(b, limits);
    EXPECT_GE(bound, reference.lower - 1e-9) << "history of " << history.size();
    EXPECT_GE(bound, without.value(b).lower - 1e-9) << "history of " << history.size();
    EXPECT_LT(bound, fresh.value(c).upper - 1e-3) << "history of " << history.size();
  }
}

}  // namespace
}  // namespace echoplan::solvers
