// report-gaussian: per class a diagonal Gaussian over (centroid, rms), variances floored at 5% of
// the pooled variance. Checked on hand-made embeddings with the fit worked out by hand.
#include "perception/report_gaussian_classifier.h"

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <numbers>

#include "../common/input_error_message.h"

namespace echoplan::perception {
namespace {

// Class 0: (1000 Hz, 0.1) and (1200 Hz, 0.3); class 1: (3000 Hz, 0.5) alone.
//   class 0 mean (1100, 0.2); own variances (10000, 0.01)
//   pooled over the three: centroid 34,320,000/9 - 27,040,000/9 = 7,280,000/9, rms 0.08/3
//   floors (5%): centroid 364,000/9 (above class 0's 10000, so it applies), rms 0.004/3
//   class 1 has one recording: both variances are the floors.
const double kCentroidFloor = 364000.0 / 9.0;
const double kRmsFloor = 0.004 / 3.0;

ReportGaussianClassifier fitted() {
  ReportGaussianClassifier c;
  const std::vector<std::vector<double>> x = {{1000, 0.1}, {1200, 0.3}, {3000, 0.5}};
  c.fit(x, std::vector<int>{0, 0, 1}, 2);
  return c;
}

// The log-density of a diagonal Gaussian in two dimensions.
double log_density(double z0, double var0, double z1, double var1) {
  return -0.5 * (z0 * z0 / var0 + z1 * z1 / var1) - 0.5 * std::log(var0 * var1) -
         std::log(2 * std::numbers::pi);
}

void expect_scores(const ClassScores& s) {
  ASSERT_EQ(s.distances.size(), 2u);
  // (1100, 0.3): class 0 at (0, 0.1) from its mean, rms variance 0.01: Mahalanobis distance 1.
  EXPECT_NEAR(s.distances[0], 1.0, 1e-9);
  EXPECT_NEAR(s.log_scores[0], log_density(0, kCentroidFloor, 0.1, 0.01), 1e-9);
  // Class 1 at (-1900, -0.2).
  EXPECT_NEAR(s.distances[1], std::sqrt(1900.0 * 1900 / kCentroidFloor + 0.04 / kRmsFloor), 1e-9);
  EXPECT_NEAR(s.log_scores[1], log_density(-1900, kCentroidFloor, -0.2, kRmsFloor), 1e-9);
}

TEST(ReportGaussian, FitsFlooredDiagonalGaussians) {
  const ReportGaussianClassifier c = fitted();
  EXPECT_EQ(c.num_classes(), 2);
  expect_scores(c.score(std::vector<double>{1100, 0.3}));
}

TEST(ReportGaussian, SavedFitLoadsBackToTheSameScores) {
  const nlohmann::json saved = fitted().save();
  EXPECT_EQ(saved["features"], nlohmann::json({"centroid_hz", "rms"}));
  ASSERT_EQ(saved["means"].size(), 2u);
  EXPECT_NEAR(saved["means"][0][0].get<double>(), 1100.0, 1e-9);
  EXPECT_NEAR(saved["means"][0][1].get<double>(), 0.2, 1e-12);
  EXPECT_NEAR(saved["variances"][1][0].get<double>(), kCentroidFloor, 1e-6);
  ReportGaussianClassifier loaded;
  loaded.load(saved, "model.json");
  EXPECT_EQ(loaded.num_classes(), 2);
  expect_scores(loaded.score(std::vector<double>{1100, 0.3}));
}

TEST(ReportGaussian, BadInputIsAnInputError) {
  ReportGaussianClassifier c;
  const std::vector<std::vector<double>> x = {{1000, 0.1}};
  EXPECT_EQ(input_error_message([&] { c.fit(x, std::vector<int>{0}, 2); }),
            "class 1 has no training recordings");
  const std::vector<std::vector<double>> three = {{1000, 0.1, 7}};
  EXPECT_NE(input_error_message([&] { c.fit(three, std::vector<int>{0}, 1); }), "(no InputError)");
  EXPECT_NE(input_error_message([&] { fitted().score(std::vector<double>{1}); }),
            "(no InputError)");
  nlohmann::json zero = fitted().save();
  zero["variances"][0][1] = 0.0;
  EXPECT_EQ(input_error_message([&] { c.load(zero, "m.json"); }),
            "m.json: classifier.variances: every variance must be positive");
  nlohmann::json none = fitted().save();
  none["means"] = nlohmann::json::array();
  EXPECT_EQ(input_error_message([&] { c.load(none, "m.json"); }),
            "m.json: classifier.means: expected at least one class");
}

}  // namespace
}  // namespace echoplan::perception
