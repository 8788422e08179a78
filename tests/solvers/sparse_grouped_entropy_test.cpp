// The sparse sum of the policy leaf's expected decision entropy against its definition, computed
// here outcome by outcome from normalised posteriors.
#include "solvers/sparse_grouped_entropy.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "common/rng.h"

namespace echoplan::solvers {
namespace {

constexpr int kActions = 3, kStates = 12, kOutcomes = 20, kGroups = 4;

// Rows of a base value with `exceptions` outcomes of their own (one of them impossible, 0), as
// a feature set's shrunk tables are: [(i * states + l) * outcomes + o].
std::vector<double> sparse_rows(int exceptions, Rng& rng) {
  std::vector<double> rows;
  for (int r = 0; r < kActions * kStates; ++r) {
    std::vector<double> row(kOutcomes, 1.0);
    for (int x = 0; x < exceptions; ++x)
      row[static_cast<int>(uniform01(rng) * kOutcomes)] =
          x == 0 ? 0.0 : 1.0 + 20.0 * uniform01(rng);
    double total = 0.0;
    for (double p : row) total += p;
    for (double& p : row) rows.push_back(p / total);
  }
  return rows;
}

// State l in group l mod kGroups.
std::vector<int> four_groups() {
  std::vector<int> group(kStates);
  for (int l = 0; l < kStates; ++l) group[l] = l % kGroups;
  return group;
}

// Σ_o P(o) H(group | o) at the belief b, the definition.
double by_definition(const std::vector<double>& rows, const std::vector<int>& group, int i,
                     const std::vector<double>& b, int outcomes = kOutcomes) {
  double expected = 0.0;
  for (int o = 0; o < outcomes; ++o) {
    std::vector<double> mass(kGroups, 0.0);
    double p = 0.0;
    for (int l = 0; l < kStates; ++l) {
      const double joint = b[l] * rows[(static_cast<std::size_t>(i) * kStates + l) * outcomes + o];
      mass[group[l]] += joint;
      p += joint;
    }
    if (p <= 0.0) continue;
    double h = 0.0;
    for (double m : mass)
      if (m > 0.0) h -= (m / p) * std::log(m / p);
    expected += p * h;
  }
  return expected;
}

TEST(SparseGroupedEntropy, EqualsTheDefinitionOnRowsOfOneValueAndAFewExceptions) {
  Rng rng(3);
  const std::vector<double> rows = sparse_rows(4, rng);
  const std::vector<int> group = four_groups();
  const SparseGroupedEntropy sparse(rows, kActions, kStates, kOutcomes, kGroups, group);
  // At most 4 exceptions a row (drawn outcomes may repeat), at least 1 (the impossible one).
  EXPECT_LE(sparse.mean_exceptions(), 4.0);
  EXPECT_GE(sparse.mean_exceptions(), 1.0);
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<double> b(kStates);
    double total = 0.0;
    for (double& p : b) p = trial == 0 ? 1.0 : std::pow(uniform01(rng), 3);
    if (trial == 1) b[5] = 0.0;  // a state the belief rules out
    for (double p : b) total += p;
    for (double& p : b) p /= total;
    for (int i = 0; i < kActions; ++i)
      EXPECT_NEAR(sparse.expected_entropy(i, b.data()), by_definition(rows, group, i, b), 1e-12)
          << "belief " << trial << ", action " << i;
  }
}

// A graded table (docs/perception.md, "Graded observations"): outcome h@g is P(h | s) times
// P(g | right) when h is the state's own class, P(g | wrong) otherwise, so each grade has a base
// value of its own in a row: one class per grade, and the exceptions are the label table's (each
// three times) and the state's own class.
TEST(SparseGroupedEntropy, GivesEachGradeOfAGradedTableABaseValue) {
  Rng rng(11);
  const std::vector<double> labels = sparse_rows(3, rng);
  constexpr int kGrades = 3, kGraded = kOutcomes * kGrades;
  const double right[kGrades] = {0.1, 0.3, 0.6}, wrong[kGrades] = {0.5, 0.3, 0.2};
  std::vector<double> rows;
  for (int r = 0; r < kActions * kStates; ++r) {
    const int own = r % kStates % kOutcomes;
    for (int g = 0; g < kGrades; ++g)
      for (int h = 0; h < kOutcomes; ++h)
        rows.push_back(labels[static_cast<std::size_t>(r) * kOutcomes + h] *
                       (h == own ? right[g] : wrong[g]));
  }
  const std::vector<int> group = four_groups();
  const SparseGroupedEntropy sparse(rows, kActions, kStates, kGraded, kGroups, group);
  // At most (3 + 1) x 3 a row, where one base value per row would leave two grades' worth.
  EXPECT_LE(sparse.mean_exceptions(), 12.0);
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<double> b(kStates);
    double total = 0.0;
    for (double& p : b) total += p = std::pow(uniform01(rng), 3);
    for (double& p : b) p /= total;
    for (int i = 0; i < kActions; ++i)
      EXPECT_NEAR(sparse.expected_entropy(i, b.data()), by_definition(rows, group, i, b, kGraded),
                  1e-12)
          << "belief " << trial << ", action " << i;
  }
}

TEST(SparseGroupedEntropy, CountsEveryOutcomeOfADenseRowAsAnException) {
  Rng rng(5);
  std::vector<double> rows;
  for (int r = 0; r < kActions * kStates * kOutcomes; ++r) rows.push_back(0.5 + uniform01(rng));
  std::vector<int> group(kStates, 0);
  const SparseGroupedEntropy dense(rows, kActions, kStates, kOutcomes, 1, group);
  // All values differ: one of them is the base, the other outcomes exceptions.
  EXPECT_DOUBLE_EQ(dense.mean_exceptions(), kOutcomes - 1);
  // One group: knowing the outcome never leaves doubt about it.
  const std::vector<double> b(kStates, 1.0 / kStates);
  EXPECT_NEAR(dense.expected_entropy(0, b.data()), 0.0, 1e-12);
}

// The policy's pruning bound, from the class's terms: −Σ_k m_k log m_k + outcome_term − state_term
// is H(group) − I(state; outcome) (the definition's, for a belief summing to 1), never above the
// expected entropy, and scales with the belief's sum as the expected entropy does; with the top
// group's slack (the definition's) added, still never above it.
TEST(SparseGroupedEntropy, ItsTermsGiveTheInformationBoundBelowTheExpectedEntropy) {
  Rng rng(7);
  const std::vector<double> rows = sparse_rows(5, rng);
  const std::vector<int> group = four_groups();
  const SparseGroupedEntropy sparse(rows, kActions, kStates, kOutcomes, kGroups, group);
  const auto bound = [&](int i, const std::vector<double>& b) {
    std::vector<double> mass(kGroups, 0.0);
    for (int l = 0; l < kStates; ++l) mass[group[l]] += b[l];
    double h = 0.0;
    for (double m : mass)
      if (m > 0.0) h -= m * std::log(m);
    sparse.set_belief(b.data());
    return h + sparse.outcome_term(i) - sparse.state_term(i);
  };
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<double> b(kStates);
    double total = 0.0;
    for (double& p : b) total += p = std::pow(uniform01(rng), 2);
    for (double& p : b) p /= total;
    for (int i = 0; i < kActions; ++i) {
      // H(group) − I(state; outcome) by the definition.
      std::vector<double> mass(kGroups, 0.0), outcome(kOutcomes, 0.0);
      const auto row = [&](int l) {
        return &rows[(static_cast<std::size_t>(i) * kStates + l) * kOutcomes];
      };
      for (int l = 0; l < kStates; ++l) {
        mass[group[l]] += b[l];
        for (int o = 0; o < kOutcomes; ++o) outcome[o] += b[l] * row(l)[o];
      }
      double reference = 0.0;
      for (double m : mass)
        if (m > 0.0) reference -= m * std::log(m);
      for (int l = 0; l < kStates; ++l)
        for (int o = 0; o < kOutcomes; ++o)
          if (row(l)[o] > 0.0) reference -= b[l] * row(l)[o] * std::log(row(l)[o] / outcome[o]);
      EXPECT_NEAR(bound(i, b), reference, 1e-12) << "belief " << trial << ", action " << i;
      EXPECT_LE(bound(i, b), by_definition(rows, group, i, b) + 1e-12);
      // The top group's slack: its g log g below m log m + Σ b Σ P log P, by the definition.
      int top = 0;
      for (int k = 1; k < kGroups; ++k)
        if (mass[k] > mass[top]) top = k;
      double slack = mass[top] * std::log(mass[top]);
      for (int l = 0; l < kStates; ++l)
        if (group[l] == top)
          for (int o = 0; o < kOutcomes; ++o)
            if (row(l)[o] > 0.0) slack += b[l] * row(l)[o] * std::log(row(l)[o]);
      for (int o = 0; o < kOutcomes; ++o) {
        double g = 0.0;
        for (int l = 0; l < kStates; ++l)
          if (group[l] == top) g += b[l] * row(l)[o];
        if (g > 0.0) slack -= g * std::log(g);
      }
      sparse.set_belief(b.data());
      sparse.outcome_term(i);
      EXPECT_NEAR(sparse.top_group_slack(i), slack, 1e-12)
          << "belief " << trial << ", action " << i;
      EXPECT_GE(sparse.top_group_slack(i), 0.0);
      EXPECT_LE(bound(i, b) + sparse.top_group_slack(i), by_definition(rows, group, i, b) + 1e-12);
      std::vector<double> half = b;
      for (double& p : half) p *= 0.5;
      EXPECT_NEAR(bound(i, half), 0.5 * bound(i, b), 1e-12);
      EXPECT_NEAR(sparse.expected_entropy(i, half.data()), 0.5 * by_definition(rows, group, i, b),
                  1e-12);
    }
  }
}

}  // namespace
}  // namespace echoplan::solvers
