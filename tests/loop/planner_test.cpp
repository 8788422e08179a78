// make_planner(): the solver, search options and budget a problem file and a user's overrides ask
// for, and how they are described in logs. The shipped problems are the fixtures:
// audio_objects.yaml asks for abt, 2000 ms per step, depth 100, exploration 110 and 1000 particles;
// tiger.pomdp has no planner section (abt, 1000 episodes per step).
#include "loop/planner.h"

#include <gtest/gtest.h>

#include <typeinfo>

#include "../common/source_dir.h"
#include "common/error.h"
#include "solvers/abt_solver.h"
#include "solvers/baseline_strategies.h"
#include "solvers/pomcp_solver.h"

namespace echoplan::loop {
namespace {

std::string shipped(const std::string& name) {
  return echoplan::testing::source_dir() + "/problems/" + name;
}

TEST(Planner, TheProblemFilesPlannerByDefault) {
  const std::string path = shipped("audio_objects.yaml");
  const Planner p = make_planner({}, pomdp::load_problem(path), path);
  EXPECT_EQ(p.name, "abt");
  EXPECT_EQ(typeid(*p.solver), typeid(solvers::AbtSolver));
  EXPECT_EQ(p.options.exploration, 110.0);
  EXPECT_EQ(p.options.max_depth, 100);
  EXPECT_EQ(p.options.root_particles, 1000);
  EXPECT_EQ(p.describe(), "abt, 2000 ms/step");
  const nlohmann::json expected = {{"solver", "abt"},
                                   {"budget", {{"step_ms", 2000}}},
                                   {"search",
                                    {{"exploration", 110.0},
                                     {"max_depth", 100},
                                     // ABT on an identification problem: the default policy leaf
                                     {"leaf", "policy"},
                                     // unheard outcomes share the heard ones' values (the default)
                                     {"unheard", "share"},
                                     {"expand_after", solvers::LeafOptions{}.expand_after},
                                     {"root_particles", 1000},
                                     {"branch_threshold", 0.0}}}};
  EXPECT_EQ(p.to_json(), expected);
}

TEST(Planner, OverridesChooseTheSolverAndBudget) {
  const std::string path = shipped("tiger.pomdp");
  solvers::PlannerOverrides f;
  f.solver = "pomcp";
  f.episodes = 250;
  f.depth = 9;
  const Planner p = make_planner(f, pomdp::load_problem(path), path);
  EXPECT_EQ(p.name, "pomcp");
  EXPECT_EQ(typeid(*p.solver), typeid(solvers::PomcpSolver));
  EXPECT_EQ(p.options.max_depth, 9);
  EXPECT_EQ(p.describe(), "pomcp, 250 episodes/step");
  EXPECT_EQ(p.to_json()["budget"], nlohmann::json({{"episodes", 250}}));
}

TEST(Planner, BadChoicesAreInputErrors) {
  const std::string path = shipped("tiger.pomdp");
  const pomdp::Problem problem = pomdp::load_problem(path);
  solvers::PlannerOverrides unknown;
  unknown.solver = "greedy";
  EXPECT_THROW(make_planner(unknown, problem, path), InputError);
  // A policy file is only for the offline solver: with an online one it would be ignored.
  solvers::PlannerOverrides policy;
  policy.policy = "policy.json";
  EXPECT_THROW(make_planner(policy, problem, path), InputError);
  // The offline solver loads the policy file it is given (here: none there).
  solvers::PlannerOverrides offline = policy;
  offline.solver = "offline";
  offline.policy = "/nonexistent/policy.json";
  EXPECT_THROW(make_planner(offline, problem, path), InputError);
}

TEST(Planner, TheBaselineStrategiesArePlannersByName) {
  const std::string path = shipped("audio_objects.yaml");
  const pomdp::Problem problem = pomdp::load_problem(path);
  for (const std::string& name : solvers::strategy_names()) {
    solvers::PlannerOverrides f;
    f.solver = name;
    EXPECT_NO_THROW(check_planner(f, problem)) << name;
    const Planner p = make_planner(f, problem, path);
    EXPECT_EQ(p.name, name);
    EXPECT_EQ(p.describe(), name + " (fixed strategy, no search)");  // no budget to spend
    ASSERT_NE(p.solver, nullptr);
  }
  // A strategy needs objects to sort: the tiger is not an identification problem of objects.
  const std::string tiger = shipped("tiger.pomdp");
  solvers::PlannerOverrides f;
  f.solver = "random";
  EXPECT_THROW(make_planner(f, pomdp::load_problem(tiger), tiger), InputError);
  // The unknown-name message lists every name a user may type.
  f.solver = "greedy";
  try {
    check_planner(f, problem);
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(),
                 "solver 'greedy' is not one of abt, pomcp, offline, all_actions, best_single, "
                 "decision_region, information_gain, random");
  }
}

}  // namespace
}  // namespace echoplan::loop
