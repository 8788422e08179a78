#include "perception/observation_table.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace echoplan::perception {
namespace {

TEST(ShrunkTable, PooledPriorSpreadsRightSameBinAndOtherBinByHand) {
  // Classes 0, 1 in bin 0; class 2 in bin 1. Counts: right 6, same bin 2 (0->1, 1->0), other
  // bin 1 (2->0). Pooled with one pseudo-count each: right 7, same 3, other 2 (sum 12).
  const std::vector<std::vector<double>> counts{{3, 1, 0}, {1, 2, 0}, {1, 0, 1}};
  const std::vector<int> bins{0, 0, 1};
  const Table prior = pooled_prior(counts, bins);
  // Class 0: right 7, same (class 1) 3, other (class 2) 2: /12.
  EXPECT_NEAR(prior[0][0], 7.0 / 12, 1e-12);
  EXPECT_NEAR(prior[0][1], 3.0 / 12, 1e-12);
  EXPECT_NEAR(prior[0][2], 2.0 / 12, 1e-12);
  // Class 2 is alone in its bin: right 7, other 2 / 2 each; renormalised by 9.
  EXPECT_NEAR(prior[2][2], 7.0 / 9, 1e-12);
  EXPECT_NEAR(prior[2][0], 1.0 / 9, 1e-12);
  EXPECT_NEAR(prior[2][1], 1.0 / 9, 1e-12);
}

TEST(ShrunkTable, RowsFollowTheirCountsWhenTheyDisagreeStronglyWithThePool) {
  // Class 0 is always right, class 1 always reported as class 0 (100 decisions each): the pool
  // says 50% right, but rows this different make a small prior strength the likely one.
  const std::vector<std::vector<double>> counts{{100, 0}, {100, 0}};
  const ShrunkTable t = shrink_counts(counts, std::vector<int>{0, 1});
  EXPECT_GT(t.table[0][0], 0.95);
  EXPECT_GT(t.table[1][0], 0.95);
  EXPECT_GT(t.table[1][1], 0.0);
  for (const auto& row : t.table) EXPECT_NEAR(row[0] + row[1], 1.0, 1e-12);
}

TEST(ShrunkTable, RowsOfFewCountsFromOneStructureShrinkToThePool) {
  // 50 classes, each heard right 3 times in 4 and once as a random other class: every row is the
  // same structure (P(right) = 3/4), so the pool explains the data and a strong prior is fitted.
  const int k = 50;
  std::vector<std::vector<double>> counts(k, std::vector<double>(k, 0.0));
  for (int c = 0; c < k; ++c) {
    counts[c][c] = 3;
    counts[c][(c + 1 + c * 7 % (k - 1)) % k] += 1;
  }
  std::vector<int> bins(k);
  for (int c = 0; c < k; ++c) bins[c] = c;
  const ShrunkTable t = shrink_counts(counts, bins);
  EXPECT_GT(t.strength, 20.0);
  // Pooled P(right) = (150 + 1) / (200 + 2) = 0.748; the rows' own estimate is 0.75.
  for (int c = 0; c < k; ++c) EXPECT_NEAR(t.table[c][c], 0.75, 0.01);
}

TEST(ShrunkTable, TemperRenormalisesPowers) {
  const Table t = temper({{0.8, 0.2}}, 0.5);
  // sqrt(0.8) = 2 sqrt(0.2): 2/3 and 1/3.
  EXPECT_NEAR(t[0][0], 2.0 / 3, 1e-12);
  EXPECT_NEAR(t[0][1], 1.0 / 3, 1e-12);
}

TEST(ShrunkTable, SequenceNllByHand) {
  const Table t{{0.8, 0.2}, {0.2, 0.8}};
  const std::vector<Sequence> s{{0, {0, 0}}};
  // Posterior of class 0 after two 0s: 0.64 / (0.64 + 0.04).
  EXPECT_NEAR(sequence_nll(t, 1.0, s), -std::log(0.64 / 0.68), 1e-12);
}

// Two classes heard right 4 times in 5 by the table. Fully correlated sessions: a session's eight
// repeats all give the same symbol, right in 80% of sessions. The posterior after eight equal
// symbols should be 0.8, so 4^(8 beta) = 4: beta = 1/8. Independent repeats need no tempering.
TEST(ShrunkTable, TemperingUndoesTheOverconfidenceOfCorrelatedRepeats) {
  const Table t{{0.8, 0.2}, {0.2, 0.8}};
  std::vector<Sequence> correlated;
  for (int i = 0; i < 100; ++i) {
    const int truth = i % 2;
    const int heard = i % 10 < 8 ? truth : 1 - truth;
    correlated.push_back({truth, std::vector<int>(8, heard)});
  }
  const double beta = fit_temper(t, correlated);
  EXPECT_NEAR(beta, 0.125, 0.005);
  // Untempered, the 20% wrong sessions cost 8 log 4 = 11 nats each.
  EXPECT_GT(sequence_nll(t, 1.0, correlated), 3.0 * sequence_nll(t, beta, correlated));

  std::mt19937_64 rng(3);
  std::vector<Sequence> independent;
  for (int i = 0; i < 2000; ++i) {
    Sequence s{i % 2, {}};
    for (int r = 0; r < 8; ++r)
      s.symbols.push_back(rng() % 5 < 4 ? s.true_class : 1 - s.true_class);
    independent.push_back(s);
  }
  EXPECT_GT(fit_temper(t, independent), 0.9);
}

}  // namespace
}  // namespace echoplan::perception
