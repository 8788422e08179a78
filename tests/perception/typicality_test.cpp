#include "perception/typicality.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace echoplan::perception {
namespace {

// Two classes, two actions, one fold each: an action hears the class right with probability 0.8.
const Table kTable{{0.8, 0.2}, {0.2, 0.8}};

// `sessions` sessions of a random class; each action's symbol drawn from kTable, except that a
// share `lookalike` sound like the other class: both actions hear it through the other class's
// row, the mixture typicality.h models, so the fit should find that share.
std::vector<HeldOutPerformances> sessions_of(int sessions, unsigned seed, double lookalike) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<HeldOutPerformances> actions(2);
  for (auto& a : actions) a.cross_fitted = {kTable};
  for (int s = 0; s < sessions; ++s) {
    const int truth = u(rng) < 0.5 ? 0 : 1;
    const bool sounds_other = u(rng) < lookalike;
    for (auto& a : actions) {
      const double right = sounds_other ? 0.2 : 0.8;
      a.session.push_back(s);
      a.fold.push_back(0);
      a.label.push_back(truth);
      a.symbol.push_back(u(rng) < right ? truth : 1 - truth);
    }
  }
  return actions;
}

TEST(Typicality, SequencesArePrefixesOfEachSessionsPerformancesInRoundsOfItsBehaviours) {
  std::vector<HeldOutPerformances> actions(2);
  for (auto& a : actions) a.cross_fitted = {kTable, kTable};  // two folds
  // Session 0 (fold 1, class 1): press heard 1 then 0, strike heard 0. Session 1 (fold 0,
  // class 0): strike heard 1.
  actions[0] = {{0, 0}, {1, 1}, {1, 1}, {1, 0}, {kTable, kTable}};
  actions[1] = {{0, 1}, {1, 0}, {1, 0}, {0, 1}, {kTable, kTable}};
  const std::vector<Sequence> s = cross_behaviour_sequences(actions);
  // Session 0: press, press+strike, then press's repeat; session 1: strike alone.
  ASSERT_EQ(s.size(), 4u);
  EXPECT_EQ(s[0].symbols, (std::vector<int>{1}));
  EXPECT_EQ(s[0].tables, (std::vector<int>{1}));  // press (action 0) fold 1
  EXPECT_EQ(s[1].symbols, (std::vector<int>{1, 0}));
  EXPECT_EQ(s[1].tables, (std::vector<int>{1, 3}));  // then strike (action 1) fold 1
  EXPECT_EQ(s[1].true_class, 1);
  EXPECT_EQ(s[2].symbols, (std::vector<int>{1, 0, 0}));  // the second round: press again
  EXPECT_EQ(s[2].tables, (std::vector<int>{1, 3, 1}));
  EXPECT_EQ(s[3].symbols, (std::vector<int>{1}));
  EXPECT_EQ(s[3].tables, (std::vector<int>{2}));  // strike fold 0
  EXPECT_EQ(s[3].true_class, 0);
}

// A lookalike of class 0 is class 1 (the only other) heard through class 0's row: by hand for two
// agreeing symbols.
TEST(Typicality, TheLookalikeNllIsItsMixturesPosteriorOfTheTrueClass) {
  Sequence s;
  s.true_class = 0;
  s.symbols = {0, 0};
  s.tables = {0, 0};
  const double rho = 0.2;
  const double right = (1 - rho) * 0.64 + rho * 0.04;  // P(0, 0 | class 0)
  const double wrong = (1 - rho) * 0.04 + rho * 0.64;  // P(0, 0 | class 1)
  const std::vector<Sequence> one{s};
  EXPECT_NEAR(lookalike_nll(std::vector<Table>{kTable}, rho, one),
              -std::log(right / (right + wrong)), 1e-12);
  // rho 0: the product of the tables.
  EXPECT_NEAR(lookalike_nll(std::vector<Table>{kTable}, 0.0, one), -std::log(0.64 / (0.64 + 0.04)),
              1e-12);
}

TEST(Typicality, ObjectsThatSoundLikeTheOtherClassGetTheirShare) {
  EXPECT_LT(fit_lookalike_share(sessions_of(4000, 3, 0.0)), 0.03);
  EXPECT_NEAR(fit_lookalike_share(sessions_of(4000, 4, 0.15)), 0.15, 0.05);
  EXPECT_EQ(fit_lookalike_share({}), 0.0);
}

// The lookalike share sees each session's whole sequence only: where the behaviours hear each
// session decisively (0.999 right), the share is the share of sessions heard as the other class,
// ns / n, however their first performances went (the mixture's likelihood is then about
// (1 - rho)^(n - ns) rho^ns, maximal at ns / n).
TEST(Typicality, TheLookalikeShareIsFittedOnEachSessionsWholeSequence) {
  const Table sharp{{0.999, 0.001}, {0.001, 0.999}};
  std::vector<HeldOutPerformances> actions(3);
  for (auto& a : actions) a.cross_fitted = {sharp};
  // 40 sessions of class 0. Sessions 0-9 sound like class 1: all three behaviours hear 1. Sessions
  // 10-19 slip once: the behaviour they start with (session s starts at s mod 3) hears 1, the other
  // two hear 0, so their whole sequences are heard as class 0 while their first prefix is not.
  for (int s = 0; s < 40; ++s)
    for (int a = 0; a < 3; ++a) {
      actions[a].session.push_back(s);
      actions[a].fold.push_back(0);
      actions[a].label.push_back(0);
      const bool other = s < 10 || (s < 20 && a == s % 3);
      actions[a].symbol.push_back(other ? 1 : 0);
    }
  const std::vector<Sequence> whole = whole_session_sequences(actions);
  ASSERT_EQ(whole.size(), 40u);
  for (const Sequence& w : whole) EXPECT_EQ(w.symbols.size(), 3u);
  EXPECT_NEAR(fit_lookalike_share(actions), 10.0 / 40.0, 0.005);
  // Every prefix would have counted the slips' first performances against class 0 as well.
  const std::vector<Table> tables{sharp, sharp, sharp};
  const std::vector<Sequence> prefixes = cross_behaviour_sequences(actions);
  EXPECT_LT(lookalike_nll(tables, 0.3, prefixes), lookalike_nll(tables, 0.25, prefixes));
}

}  // namespace
}  // namespace echoplan::perception
