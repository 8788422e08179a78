// Copying a TabularModel: terminal states made exact, and tables that are not distributions
// rejected.
#include "solvers/offline/flat_pomdp.h"

#include <gtest/gtest.h>

#include "common/error.h"
#include "test_problems.h"

namespace echoplan::solvers::offline {
namespace {

void expect_rejected(const testing::TableModel& m, const std::string& fragment) {
  try {
    make_flat_pomdp(m, "problem.yaml");
    ADD_FAILURE() << "accepted a model that should fail with: " << fragment;
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "problem.yaml");
    EXPECT_NE(e.problem().find(fragment), std::string::npos) << e.what();
  }
}

TEST(FlatPomdp, TerminalStatesAreAbsorbingWithZeroReward) {
  testing::TableModel m = testing::audio_objects();
  // Even if the tables give the terminal state a reward and a way out, it stays put at 0.
  m.R[testing::kDone] = {5, 5, 5, 5};
  m.T[testing::kSlide][testing::kDone] = {1, 0, 0, 0, 0};
  const FlatPomdp d = make_flat_pomdp(m);
  for (int a = 0; a < d.num_actions; ++a) {
    EXPECT_EQ(d.reward_at(testing::kDone, a), 0.0);
    ASSERT_EQ(d.successors_of(testing::kDone, a).size(), 1u);
    EXPECT_EQ(d.successors_of(testing::kDone, a)[0].state, testing::kDone);
  }
  // Deterministic transitions are stored with a single successor.
  EXPECT_EQ(d.successors_of(0, testing::kStrike).size(), 1u);
}

TEST(FlatPomdp, RejectsTablesThatAreNotDistributions) {
  testing::TableModel m = testing::tiger();
  m.T[0][1] = {0.2, 0.7};
  expect_rejected(m, "transition row of state 1 action 0 sums to 0.9");

  m = testing::tiger();
  m.Z[0][0] = {0.85, 0.25};
  expect_rejected(m, "observation row of action 0 state 0 sums to 1.1");

  m = testing::tiger();
  m.Z[0][0] = {1.5, -0.5};
  expect_rejected(m, "not a probability");

  m = testing::tiger();
  m.b0 = {0.5};
  expect_rejected(m, "initial belief has 1 entries for 2 states");

  m = testing::tiger();
  m.b0 = {0.6, 0.6};
  expect_rejected(m, "initial belief sums to 1.2");

  m = testing::tiger();
  m.gamma = 1.0;
  expect_rejected(m, "discount 1 is outside (0, 1)");
}

}  // namespace
}  // namespace echoplan::solvers::offline
