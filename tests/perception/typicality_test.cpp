#include "perception/typicality.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace echoplan::perception {
namespace {

// Two classes, two actions, one fold each: an action hears the class right with probability 0.8.
const Table kTable{{0.8, 0.2}, {0.2, 0.8}};

// `sessions` sessions of a random class; each action's symbol drawn from kTable, except that a
// share `blind` of the sessions are atypical: both actions hear a fair coin (the class-blind row
// of kTable is {0.5, 0.5}), the mixture typicality.h models, so the fit should find rho = blind.
std::vector<HeldOutPerformances> sessions_of(int sessions, double blind, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<HeldOutPerformances> actions(2);
  for (auto& a : actions) a.cross_fitted = {kTable};
  for (int s = 0; s < sessions; ++s) {
    const int truth = u(rng) < 0.5 ? 0 : 1;
    const bool atypical = u(rng) < blind;
    for (auto& a : actions) {
      const double right = atypical ? 0.5 : 0.8;
      a.session.push_back(s);
      a.fold.push_back(0);
      a.label.push_back(truth);
      a.symbol.push_back(u(rng) < right ? truth : 1 - truth);
    }
  }
  return actions;
}

TEST(Typicality, SequencesArePrefixesOfEachSessionsBehavioursInARotatedOrder) {
  std::vector<HeldOutPerformances> actions(2);
  for (auto& a : actions) a.cross_fitted = {kTable, kTable};  // two folds
  // Session 0 (fold 1, class 1): press heard 1 then 0 (only the first counts), strike heard 0.
  actions[0] = {{0, 0}, {1, 1}, {1, 1}, {1, 0}, {kTable, kTable}};
  actions[1] = {{0, 1}, {1, 0}, {1, 0}, {0, 1}, {kTable, kTable}};
  const std::vector<Sequence> s = cross_behaviour_sequences(actions);
  ASSERT_EQ(s.size(), 3u);  // session 0: press, then press+strike; session 1: strike alone
  EXPECT_EQ(s[0].symbols, (std::vector<int>{1}));
  EXPECT_EQ(s[0].tables, (std::vector<int>{1}));  // press (action 0) fold 1
  EXPECT_EQ(s[1].symbols, (std::vector<int>{1, 0}));
  EXPECT_EQ(s[1].tables, (std::vector<int>{1, 3}));  // then strike (action 1) fold 1
  EXPECT_EQ(s[1].true_class, 1);
  EXPECT_EQ(s[2].symbols, (std::vector<int>{1}));
  EXPECT_EQ(s[2].tables, (std::vector<int>{2}));  // strike fold 0
  EXPECT_EQ(s[2].true_class, 0);
}

// The mixture's posterior by hand for one sequence of two agreeing symbols.
TEST(Typicality, TheNllIsTheMixturesPosteriorOfTheTrueClass) {
  Sequence s;
  s.true_class = 0;
  s.symbols = {0, 0};
  s.tables = {0, 0};
  const double rho = 0.2;
  const double right = (1 - rho) * 0.8 * 0.8 + rho * 0.25;  // class-blind row {0.5, 0.5}
  const double wrong = (1 - rho) * 0.2 * 0.2 + rho * 0.25;
  const std::vector<Sequence> one{s};
  EXPECT_NEAR(typicality_nll(std::vector<Table>{kTable}, rho, one),
              -std::log(right / (right + wrong)), 1e-12);
  // rho 0: the product of the tables.
  EXPECT_NEAR(typicality_nll(std::vector<Table>{kTable}, 0.0, one), -std::log(0.64 / (0.64 + 0.04)),
              1e-12);
}

TEST(Typicality, IndependentBehavioursGetNoShareAndClassBlindOnesTheirShare) {
  EXPECT_LT(fit_atypical_share(sessions_of(4000, 0.0, 1)), 0.03);
  EXPECT_NEAR(fit_atypical_share(sessions_of(4000, 0.3, 2)), 0.3, 0.08);
  EXPECT_EQ(fit_atypical_share({}), 0.0);
}

TEST(Typicality, TheClassBlindRowIsTheMeanOfTheClassRows) {
  EXPECT_EQ(class_blind_row({{0.8, 0.2, 0.0}, {0.2, 0.6, 0.2}}),
            (std::vector<double>{0.5, 0.4, 0.1}));
}

}  // namespace
}  // namespace echoplan::perception
