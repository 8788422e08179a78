// read_identification_tables() on the report's shipped problem: the live states, the terminal
// actions, the emission and known-value tables the exact solver, the sensing policy and the pair
// relaxation share; and a sensing policy on shared tables behaves as one reading its own.
#include "solvers/identification_tables.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "../common/source_dir.h"
#include "pomdp/problem.h"
#include "solvers/sensing_policy.h"

namespace echoplan::solvers {
namespace {

pomdp::Problem report_problem() {
  return pomdp::load_problem(echoplan::testing::source_dir() + "/problems/audio_objects.yaml");
}

TEST(IdentificationTables, ReadsTheReportsProblemOverItsLiveStates) {
  const pomdp::Problem problem = report_problem();
  const pomdp::TabularModel& m = *problem.model->tabular();
  ASSERT_FALSE(identification_shape_problem(m).has_value());
  const auto t = read_identification_tables(m);
  EXPECT_EQ(t->states, m.num_states());
  ASSERT_EQ(t->live_states, static_cast<int>(t->model_state.size()));
  for (int s = 0, l = 0; s < m.num_states(); ++s)
    if (!m.terminal(s)) {
      EXPECT_EQ(t->model_state[l++], s);
    }
  const int L = t->live_states, O = t->observations;
  for (int a = 0; a < t->actions; ++a) {
    // Sensing keeps the state (sometimes: a collision ends the episode); sorting always ends it.
    bool keeps = false;
    for (int l = 0; l < L; ++l) {
      const int s = t->model_state[l];
      EXPECT_EQ(t->reward[a * L + l], m.reward(s, a));
      EXPECT_EQ(t->stay[a * L + l], m.transition(s, a, s));
      keeps = keeps || t->stay[a * L + l] > 0.0;
      for (int o = 0; o < O; ++o)
        EXPECT_EQ(t->emission[(a * O + o) * L + l], t->stay[a * L + l] * m.observation(a, s, o));
    }
    EXPECT_EQ(t->terminal[a], !keeps) << a;
  }
  // A known object is sorted right at once: 10.
  for (int l = 0; l < L; ++l) EXPECT_DOUBLE_EQ(t->known_value[l], 10.0);
  EXPECT_EQ(t->initial_belief, m.initial_belief());
}

TEST(IdentificationTables, ASensingPolicyOnSharedTablesMatchesOneReadingItsOwn) {
  const pomdp::Problem problem = report_problem();
  const pomdp::TabularModel& m = *problem.model->tabular();
  const SensingPolicy own(m);
  const SensingPolicy shared(read_identification_tables(m));
  std::vector<double> b0 = m.initial_belief();
  double own_returns[SensingPolicy::kThresholds] = {};
  double shared_returns[SensingPolicy::kThresholds] = {};
  Rng a(7), b(7);
  for (int i = 0; i < 200; ++i) {
    own.rollout(b0, 50, a, own_returns);
    shared.rollout(b0, 50, b, shared_returns);
  }
  for (int k = 0; k < SensingPolicy::kThresholds; ++k) EXPECT_EQ(own_returns[k], shared_returns[k]);
  EXPECT_EQ(own.choose_sensing(b0), shared.choose_sensing(b0));
}

}  // namespace
}  // namespace echoplan::solvers
