// The upper bound from every reading the use limits leave (solvers/readings_left_bound.h) against
// hand computations and the brute-force V* of limited_problems.h, and what it does for the exact
// solver's bounds.
#include "solvers/readings_left_bound.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

#include "limited_problems.h"
#include "solvers/identification_solver.h"
#include "solvers/use_limits.h"

namespace echoplan::solvers {
namespace {

using testing::brute_force_value;
using testing::grasp_then_listen;
using testing::one_noisy_sensor;
using testing::report_with_limits;

std::shared_ptr<const IdentificationTables> limited_tables(const pomdp::Model& model) {
  return read_identification_tables(*model.tabular(), UseLimits(model));
}

// Every state in the main support, so that nothing is valued as known for want of room.
ReadingsLeftOptions whole_support() {
  ReadingsLeftOptions o;
  o.min_probability = 0.0;
  o.budget = 1000000;
  o.max_readings = 100;
  return o;
}

TEST(ReadingsLeftBound, OneListenLeftIsWorthExactlySensingOnceThenSorting) {
  // One listen left (80% right; sort +10 / −100; −1; γ = 0.9): told the one outcome, the agent
  // sorts what it would sort anyway, so the bound is V* = −1 + 0.9·(0.8·10 − 0.2·100) = −11.8.
  const pomdp::ModelPtr once = one_noisy_sensor(1);
  const ReadingsLeftBound bound(limited_tables(*once));
  ASSERT_TRUE(bound.applies());
  const double b0[] = {0.5, 0.5};
  EXPECT_NEAR(bound.value(b0, nullptr), -11.8, 1e-12);
  // Listened: only the sort is left (0.8 on the heard object: −12).
  const std::uint16_t listened[] = {1, 0, 0};
  const double heard_a[] = {0.8, 0.2};
  EXPECT_NEAR(bound.value(heard_a, listened), -12.0, 1e-12);
}

TEST(ReadingsLeftBound, TwoListensLeftAreWorthTheirHandComputedValue) {
  // Told both outcomes: they agree with probability 0.34 each way (weights 0.32 and 0.02), which
  // sorts for 0.32·9 − 0.02·81 = 1.26, and disagree with probability 0.16 each way (0.08 and
  // 0.08): −5.76. A right sort is discounted at least once (9 = 0.9·10), a wrong one at most
  // twice (−81 = 0.81·(−100)). So −1 + 2·1.26 − 2·5.76 = −10.0, far below one more sensing
  // (−1 + 0.9·10 = 8) and above V* = −1 + 0.9·(−11.8) = −11.62 (listening twice never pays).
  const pomdp::ModelPtr twice = one_noisy_sensor(2);
  const ReadingsLeftBound bound(limited_tables(*twice));
  const double b0[] = {0.5, 0.5};
  EXPECT_NEAR(bound.value(b0, nullptr), -10.0, 1e-12);
  std::vector<int> uses(twice->num_actions(), 0);
  EXPECT_NEAR(brute_force_value(*twice, twice->tabular()->initial_belief(), uses), -11.62, 1e-12);

  // With no budget the outcome tree is not opened: one more sensing reveals the object.
  ReadingsLeftOptions none;
  none.budget = 0;
  EXPECT_NEAR(ReadingsLeftBound(limited_tables(*twice), none).value(b0, nullptr), 8.0, 1e-12);
}

TEST(ReadingsLeftBound, AppliesOnlyWhenEverySensingActionIsLimited) {
  EXPECT_FALSE(ReadingsLeftBound(limited_tables(*one_noisy_sensor(0))).applies());
  const double b0[] = {0.5, 0.5};
  EXPECT_EQ(ReadingsLeftBound(limited_tables(*one_noisy_sensor(0))).value(b0, nullptr),
            std::numeric_limits<double>::infinity());
  EXPECT_TRUE(ReadingsLeftBound(limited_tables(*grasp_then_listen())).applies());
  EXPECT_FALSE(ReadingsLeftBound(limited_tables(*report_with_limits(0, 2))).applies());
}

// Walks every history of `model` (each allowed action, each outcome it can hear), checking the
// bound at each belief against the brute-force V*: never below it, equal to it with one reading
// left. Returns how many beliefs it bounds below one more sensing by more than 0.1.
int check_every_history(const pomdp::Model& model, const ReadingsLeftBound& bound,
                        const IdentificationTables& t, std::vector<double>& b,
                        std::vector<int>& uses) {
  const int L = t.live_states, A = t.actions;
  std::vector<double> live(L);
  for (int l = 0; l < L; ++l) live[l] = b[t.model_state[l]];
  std::vector<std::uint16_t> used(uses.begin(), uses.end());
  const double value = bound.value(live.data(), used.data());
  const double vstar = brute_force_value(model, b, uses);
  EXPECT_GE(value, vstar - 1e-9);
  int left = 0;
  double commit = -std::numeric_limits<double>::infinity(), first = commit, known = 0.0;
  for (int a = 0; a < A; ++a) {
    double r = 0.0;
    for (int l = 0; l < L; ++l) r += live[l] * t.reward[a * L + l];
    if (t.terminal[a]) {
      commit = std::max(commit, r);
      continue;
    }
    left += t.limits.max_uses(a) - uses[a];
    if (t.limits.allows(uses, a)) first = std::max(first, r);
  }
  for (int l = 0; l < L; ++l) known += live[l] * t.known_value[l];
  if (left == 1) {
    EXPECT_NEAR(value, vstar, 1e-9);
  }
  int tighter = value < std::max(commit, first + t.discount * known) - 0.1;

  const pomdp::TabularModel& m = *model.tabular();
  for (int a = 0; a < A; ++a) {
    if (t.terminal[a] || !t.limits.allows(uses, a)) continue;
    ++uses[a];
    for (int o = 0; o < m.num_observations(); ++o) {
      std::vector<double> next(b.size(), 0.0);
      double p = 0.0;
      for (std::size_t s = 0; s < b.size(); ++s) p += next[s] = b[s] * m.observation(a, int(s), o);
      if (p <= 0.0) continue;
      for (double& x : next) x /= p;
      tighter += check_every_history(model, bound, t, next, uses);
    }
    --uses[a];
  }
  return tighter;
}

TEST(ReadingsLeftBound, BoundsVStarFromAboveAfterEveryHistory) {
  // The report's four objects, two slides and two strikes (and, second, the strike only after a
  // slide): at every belief a history reaches.
  for (const int waiting : {-1, 1}) {
    const pomdp::ModelPtr model = report_with_limits(waiting < 0 ? 2 : 1, 2, waiting);
    const auto tables = limited_tables(*model);
    const ReadingsLeftBound bound(tables, whole_support());
    std::vector<double> b = model->tabular()->initial_belief();
    std::vector<int> uses(model->num_actions(), 0);
    EXPECT_GT(check_every_history(*model, bound, *tables, b, uses), 0) << "waiting " << waiting;
  }
}

TEST(ReadingsLeftBound, CapsANewBeliefsUpperBoundInTheExactSolver) {
  // The report's problem with one slide and one strike: before any search, the exact solver's
  // upper bound at b0 is lower with this bound, and still above the brute-force V*.
  const pomdp::ModelPtr model = report_with_limits(1, 1);
  const auto tables = limited_tables(*model);
  std::vector<int> uses(model->num_actions(), 0);
  const double vstar = brute_force_value(*model, model->tabular()->initial_belief(), uses);
  const IdentificationSolver with(tables);
  IdentificationOptions without_options;
  without_options.readings_left_upper_bound = false;
  const IdentificationSolver without(tables, without_options);
  EXPECT_GE(with.value(with.root()).upper, vstar - 1e-9);
  EXPECT_LT(with.value(with.root()).upper, without.value(without.root()).upper - 0.1);
}

}  // namespace
}  // namespace echoplan::solvers
