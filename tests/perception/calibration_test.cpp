// Calibration: confusion counts to a Dirichlet-smoothed table, and temperature scaling.
#include "perception/calibration.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

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
