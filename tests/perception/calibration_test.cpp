// Calibration: confusion counts to a Dirichlet-smoothed table, and temperature scaling.
#include "perception/calibration.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

#include "perception/observation_table.h"

namespace echoplan::perception {
namespace {

TEST(Calibration, KnownConfusionGivesTheExpectedSmoothedTable) {
  ConfusionMatrix c = ConfusionMatrix::zeros({"mug", "cup"}, {"mug", "cup", "unknown"});
  c.counts = {{8, 2, 0}, {1, 8, 1}};
  // alpha 1 over 3 symbols: (n + 1) / (10 + 3).
  const auto table = dirichlet_smoothed(c, 1.0);
  EXPECT_DOUBLE_EQ(table[0][0], 9.0 / 13);
  EXPECT_DOUBLE_EQ(table[0][1], 3.0 / 13);
  EXPECT_DOUBLE_EQ(table[0][2], 1.0 / 13);
  EXPECT_DOUBLE_EQ(table[1][0], 2.0 / 13);
  EXPECT_DOUBLE_EQ(table[1][1], 9.0 / 13);
  EXPECT_DOUBLE_EQ(table[1][2], 2.0 / 13);
  // alpha 0 is the raw frequency; alpha 0.5 (Jeffreys): (n + 0.5) / 11.5.
  EXPECT_DOUBLE_EQ(dirichlet_smoothed(c, 0.0)[0][1], 0.2);
  EXPECT_DOUBLE_EQ(dirichlet_smoothed(c, 0.5)[1][2], 1.5 / 11.5);
  EXPECT_DOUBLE_EQ(c.accuracy(), 16.0 / 20);
  EXPECT_EQ(c.total(), 20);
}

TEST(Calibration, EmptyRowNeedsAPrior) {
  ConfusionMatrix c = ConfusionMatrix::zeros({"a", "b"}, {"a", "b"});
  c.counts = {{3, 0}, {0, 0}};
  EXPECT_THROW(dirichlet_smoothed(c, 0.0), std::invalid_argument);
  EXPECT_DOUBLE_EQ(dirichlet_smoothed(c, 2.0)[1][0], 0.5);
  EXPECT_THROW(dirichlet_smoothed(c, -1.0), std::invalid_argument);
}

TEST(Calibration, SoftConfusionOfASureClassifierIsTheHardCounts) {
  // Winning log-scores 200 above the rest at T = 1: probabilities 1 and e^-200 (~1e-87), so each
  // clip adds (numerically) one to the symbol it would be reported as. Clip 3 of object 1 is
  // rejected: its whole unit goes to `unknown` (symbol 2), as a hard count would put it.
  const std::vector<std::vector<double>> scores{{0.0, -200.0}, {0.0, -200.0}, {-200.0, 0.0},
                                                {-200.0, 0.0}, {0.0, -200.0}, {-200.0, 0.0}};
  const std::vector<int> labels{0, 0, 0, 1, 1, 1};
  const std::vector<bool> rejected{false, false, false, false, false, true};
  const auto soft = soft_confusion(scores, labels, rejected, 2, 3, 1.0);
  ConfusionMatrix hard = ConfusionMatrix::zeros({"a", "b"}, {"a", "b", "unknown"});
  hard.counts = {{2, 1, 0}, {1, 1, 1}};
  for (std::size_t k = 0; k < 2; ++k)
    for (std::size_t o = 0; o < 3; ++o) EXPECT_NEAR(soft[k][o], hard.counts[k][o], 1e-12);
  const auto smoothed = dirichlet_smoothed(soft, hard.objects, 1.0);
  const auto expected = dirichlet_smoothed(hard, 1.0);
  for (std::size_t k = 0; k < 2; ++k)
    for (std::size_t o = 0; o < 3; ++o) EXPECT_NEAR(smoothed[k][o], expected[k][o], 1e-12);
}

TEST(Calibration, NarrowMarginsGiveASofterRowThanWideOnes) {
  // Two classes, two clips of object 0, both won by class 0, at T = 2.
  //   wide:   margin 8  -> P(0) = 1 / (1 + e^-4)   = 0.98201379
  //   narrow: margin 1  -> P(0) = 1 / (1 + e^-0.5) = 0.62245933
  // Hard counts give both actions the row (2, 0) -> smoothed (3/4, 1/4). Soft rows:
  //   wide:   (1.96402758, 0.03597242) -> ((1.96402758 + 1) / 4, ...) = (0.74100690, 0.25899310)
  //   narrow: (1.24491866, 0.75508134) -> (0.56122967, 0.43877034)
  const std::vector<int> labels{0, 0};
  const std::vector<std::vector<double>> wide{{3.0, -5.0}, {1.0, -7.0}};
  const std::vector<std::vector<double>> narrow{{0.5, -0.5}, {2.0, 1.0}};
  const auto soft_wide = soft_confusion(wide, labels, {}, 2, 2, 2.0);
  const auto soft_narrow = soft_confusion(narrow, labels, {}, 2, 2, 2.0);
  EXPECT_NEAR(soft_wide[0][0], 1.96402758, 1e-8);
  EXPECT_NEAR(soft_narrow[0][0], 1.24491866, 1e-8);
  EXPECT_NEAR(soft_narrow[0][1], 0.75508134, 1e-8);
  // The row of object 1 has no clips: all zero, the prior alone fills it.
  EXPECT_DOUBLE_EQ(soft_narrow[1][0] + soft_narrow[1][1], 0.0);
  const auto wide_table = dirichlet_smoothed(soft_wide, {"a", "b"}, 1.0);
  const auto narrow_table = dirichlet_smoothed(soft_narrow, {"a", "b"}, 1.0);
  EXPECT_NEAR(wide_table[0][0], 0.74100690, 1e-8);
  EXPECT_NEAR(narrow_table[0][0], 0.56122967, 1e-8);
  EXPECT_NEAR(narrow_table[0][1], 0.43877034, 1e-8);
  EXPECT_DOUBLE_EQ(narrow_table[1][0], 0.5);
}

TEST(Calibration, SoftConfusionRejectsMismatchedInput) {
  const std::vector<std::vector<double>> scores{{0.0, 1.0}};
  EXPECT_THROW(soft_confusion(scores, std::vector<int>{2}, {}, 2, 2, 1.0), std::invalid_argument);
  EXPECT_THROW(soft_confusion(scores, std::vector<int>{0, 1}, {}, 2, 2, 1.0),
               std::invalid_argument);
  EXPECT_THROW(soft_confusion(scores, std::vector<int>{0}, {true}, 2, 2, 1.0),
               std::invalid_argument);  // rejected, but no unknown symbol
  EXPECT_THROW(soft_confusion(scores, std::vector<int>{0}, {}, 2, 4, 1.0), std::invalid_argument);
}

TEST(Calibration, SoftmaxIsStableAndTempered) {
  const std::vector<double> s{1000.0, 1000.0 - std::log(3.0)};
  const auto p = softmax(s, 1.0);
  EXPECT_NEAR(p[0], 0.75, 1e-12);
  EXPECT_NEAR(p[1], 0.25, 1e-12);
  const auto q = softmax(s, 2.0);  // exp(-ln 3 / 2) = 1 / sqrt 3
  EXPECT_NEAR(q[0], 1.0 / (1.0 + 1.0 / std::sqrt(3.0)), 1e-12);
}

TEST(Calibration, TemperatureRecoversTheOneThatGeneratedTheLabels) {
  // Labels drawn from softmax(scores / 4): the fitted temperature must come out near 4.
  std::mt19937_64 rng(3);
  std::normal_distribution<double> gauss(0.0, 10.0);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::vector<std::vector<double>> scores;
  std::vector<int> labels;
  for (int i = 0; i < 4000; ++i) {
    std::vector<double> s{gauss(rng), gauss(rng), gauss(rng)};
    const auto p = softmax(s, 4.0);
    const double u = uniform(rng);
    labels.push_back(u < p[0] ? 0 : u < p[0] + p[1] ? 1 : 2);
    scores.push_back(std::move(s));
  }
  EXPECT_NEAR(fit_temperature(scores, labels), 4.0, 0.3);
  EXPECT_DOUBLE_EQ(fit_temperature({}, {}), 1.0);
}

TEST(Calibration, SmoothingKeepsSeparableDataFromCertainty) {
  // Perfectly separated scores: without smoothing the temperature collapses to its lower bound,
  // with smoothing 0.1 the probability of the right class stays near 0.9 + 0.1 / 2.
  const std::vector<std::vector<double>> scores{{0.0, -5.0}, {-5.0, 0.0}, {0.0, -5.0}, {-5.0, 0.0}};
  const std::vector<int> labels{0, 1, 0, 1};
  EXPECT_LT(fit_temperature(scores, labels), 1e-3);
  const double t = fit_temperature(scores, labels, 0.1);
  EXPECT_NEAR(softmax(scores[0], t)[0], 0.95, 1e-3);
}

}  // namespace
}  // namespace echoplan::perception
