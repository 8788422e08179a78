// make_solver(): each name users type builds that solver with the options given; anything else is
// an InputError that lists the names.
#include "solvers/make_solver.h"

#include <gtest/gtest.h>

#include <typeinfo>

#include "../common/source_dir.h"
#include "common/error.h"
#include "common/rng.h"
#include "pomdp/make_belief.h"
#include "pomdp/problem.h"
#include "solvers/abt_solver.h"
#include "solvers/pomcp_solver.h"

namespace echoplan::solvers {
namespace {

pomdp::Problem tiger() {
  return pomdp::load_problem(echoplan::testing::source_dir() + "/problems/tiger.pomdp");
}

TEST(MakeSolver, TheNamesAreAbtAndPomcp) {
  EXPECT_EQ(solver_names(), (std::vector<std::string>{"abt", "pomcp"}));
}

TEST(MakeSolver, EachNameBuildsItsSolver) {
  const pomdp::Problem problem = tiger();
  const std::unique_ptr<Solver> abt = make_solver("abt", problem.model, {});
  const std::unique_ptr<Solver> pomcp = make_solver("pomcp", problem.model, {});
  EXPECT_EQ(typeid(*abt), typeid(AbtSolver));
  EXPECT_EQ(typeid(*pomcp), typeid(PomcpSolver));
}

TEST(MakeSolver, TheOptionsReachTheSolver) {
  // The root holds exactly root_particles states after reset(), whichever solver it is.
  const pomdp::Problem problem = tiger();
  SearchOptions options;
  options.root_particles = 37;
  for (const std::string& name : solver_names()) {
    Rng rng(5);
    const pomdp::BeliefPtr belief = pomdp::make_belief(problem, rng);
    auto solver = make_solver(name, problem.model, options);
    solver->reset(*belief, rng);
    EXPECT_EQ(solver->stats().root_particles, 37) << name;
  }
}

TEST(MakeSolver, UnknownNamesAndBadOptionsAreInputErrors) {
  const pomdp::Problem problem = tiger();
  try {
    make_solver("ABT", problem.model, {});
    FAIL() << "no InputError for an unknown name";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(),
                 "solver 'ABT' is not one of abt, pomcp, all_actions, best_single, "
                 "decision_region, information_gain, random");
  }
  SearchOptions bad;
  bad.max_depth = 0;
  for (const std::string& name : solver_names())
    EXPECT_THROW(make_solver(name, problem.model, bad), InputError) << name;
}

}  // namespace
}  // namespace echoplan::solvers
