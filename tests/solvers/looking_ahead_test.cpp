// The shipped problems where looking ahead matters (issue 54), read from problems/: at a belief the
// problem's own comment names, both greedy rules choose an action the exact solver proves worse
// than another. The solver's bounds (a search over beliefs, independent of the strategies' one-step
// rules) are the reference.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "../common/source_dir.h"
#include "pomdp/object_identification_model.h"
#include "pomdp/problem.h"
#include "solvers/baseline_strategies.h"
#include "solvers/identification_solver.h"
#include "tiny_identification_problems.h"

namespace echoplan::solvers {
namespace {

pomdp::Problem shipped(const std::string& name) {
  return pomdp::load_problem(echoplan::testing::source_dir() + "/problems/" + name);
}

int index_of(const std::vector<std::string>& names, const std::string& name) {
  for (std::size_t i = 0; i < names.size(); ++i)
    if (names[i] == name) return static_cast<int>(i);
  ADD_FAILURE() << name << " is not among the names";
  return -1;
}

// A greedy rule's choice after the sensing actions `heard` (action, symbol), at the beliefs the
// exact solver reaches along them, with the solver's node at the end.
struct AfterHearing {
  int choice = -1;
  IdentificationSolver::NodeId node = 0;
};

AfterHearing greedy_after(const std::string& rule, const pomdp::Problem& problem,
                          IdentificationSolver& solver,
                          const std::vector<std::pair<int, int>>& heard) {
  const pomdp::ObjectIdentificationModel& model = *problem.model->object_identification();
  const auto objects_at = [&](IdentificationSolver::NodeId node) {
    std::vector<double> b = solver.belief(node);
    b.resize(model.data().objects.size());  // the objects; 'done' holds nothing before the sort
    return b;
  };
  Rng rng(3);
  const std::unique_ptr<Solver> strategy = make_strategy(rule, problem.model);
  AfterHearing after;
  strategy->reset(testing::GivenBelief(objects_at(after.node)), rng);
  for (const auto& [action, symbol] : heard) {
    after.node = solver.child(after.node, action, symbol);
    strategy->update(action, {symbol, {}}, testing::GivenBelief(objects_at(after.node)), rng);
  }
  strategy->improve(Budget::episodes(1), rng);
  after.choice = strategy->best_action();
  return after;
}

Bounds refined_action_value(IdentificationSolver& solver, IdentificationSolver::NodeId node,
                            int action) {
  RefineLimits limits;
  limits.target_gap = 1e-4;
  limits.expansions = 200000;
  solver.refine_action(node, action, limits);
  return solver.action_value(node, action);
}

// Eight containers in two bins: after a strike heard a full jar and one shake agreed, both rules
// sort to A (belief in full 0.85: 0.85 * 10 - 0.15 * 100 = -6.5), though shaking again is worth
// more than 5 above that (V* there is about 1.6).
TEST(LookingAhead, CoarseBinsGreedyRulesSortWhereAnotherShakePays) {
  const pomdp::Problem problem = shipped("coarse_bins.yaml");
  const pomdp::ObjectProblemData& d = problem.model->object_identification()->data();
  const int strike = 0, shake = 1, to_a = 2;
  ASSERT_EQ(d.sensing[shake].name, "shake");
  const int full_jar = index_of(d.observation_symbols, "full_jar");
  IdentificationSolver solver(*problem.model->tabular());
  for (const std::string rule : {"information_gain", "decision_region"}) {
    const AfterHearing after =
        greedy_after(rule, problem, solver, {{strike, full_jar}, {shake, full_jar}});
    EXPECT_EQ(after.choice, to_a) << rule;
    const Bounds sort = refined_action_value(solver, after.node, to_a);
    const Bounds shake_again = refined_action_value(solver, after.node, shake);
    EXPECT_GT(shake_again.lower, sort.upper + 5.0) << rule;
  }
}

// Cups and tins, three in ten unlike their class: at the start both rules strike (cheap, and it
// tells typical cups from tins), though on an unlike object every strike errs the same way and the
// exact solver proves a slide worth more by over 0.5 (V*(b0) 1.20, striking first about 0.19).
TEST(LookingAhead, CorrelatedRepeatsGreedyRulesStrikeWhereASlidePays) {
  const pomdp::Problem problem = shipped("correlated_repeats.yaml");
  const pomdp::ObjectProblemData& d = problem.model->object_identification()->data();
  const int strike = 0, slide = 1;
  ASSERT_EQ(d.sensing[slide].name, "slide");
  IdentificationSolver solver(*problem.model->tabular());
  for (const std::string rule : {"information_gain", "decision_region"}) {
    const AfterHearing after = greedy_after(rule, problem, solver, {});
    EXPECT_EQ(after.choice, strike) << rule;
    const Bounds by_strike = refined_action_value(solver, after.node, strike);
    const Bounds by_slide = refined_action_value(solver, after.node, slide);
    EXPECT_GT(by_slide.lower, by_strike.upper + 0.5) << rule;
  }
}

}  // namespace
}  // namespace echoplan::solvers
