// The row classifiers (the one registry): each on rows whose best accuracy is known, and each
// fit saved and loaded.
#include "perception/row_classifier.h"

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <random>

#include "../common/input_error_message.h"
#include "common/error.h"

namespace echoplan::perception {
namespace {

// Two 1-D Gaussian classes, means -1 and +1, unit variance, plus `noise_features` features of pure
// noise. The Bayes classifier thresholds the first feature at 0: accuracy Phi(1) = 0.8413.
struct TwoClasses {
  std::vector<std::vector<double>> rows;
  std::vector<int> labels;
};

TwoClasses two_classes(int per_class, int noise_features, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  TwoClasses d;
  for (int i = 0; i < 2 * per_class; ++i) {
    const int label = i % 2;
    std::vector<double> row{(label == 0 ? -1.0 : 1.0) + normal(rng)};
    for (int j = 0; j < noise_features; ++j) row.push_back(100.0 * normal(rng));  // other units
    d.rows.push_back(row);
    d.labels.push_back(label);
  }
  return d;
}

double accuracy(const RowClassifier& c, const TwoClasses& test) {
  int right = 0;
  for (std::size_t i = 0; i < test.rows.size(); ++i) {
    const auto s = c.score(test.rows[i]).log_scores;
    right += (s[1] > s[0] ? 1 : 0) == test.labels[i];
  }
  return static_cast<double>(right) / static_cast<double>(test.rows.size());
}

const double kBayes = 0.5 * std::erfc(-1.0 / std::sqrt(2.0));  // Phi(1)

TEST(RowClassifier, LdaReachesTheBayesAccuracyOfTwoGaussians) {
  auto lda = make_row_classifier("lda");
  const auto train = two_classes(500, 2, 1);
  lda->fit(train.rows, train.labels, 2);
  // 10,000 test rows: the standard error of an accuracy near 0.84 is 0.004.
  EXPECT_NEAR(accuracy(*lda, two_classes(5000, 2, 2)), kBayes, 0.015);
}

TEST(RowClassifier, NearestNeighbourIsWithinCoverAndHartsBound) {
  // 1-NN's asymptotic error lies between the Bayes error R and 2R(1 - R) (Cover and Hart 1967).
  auto nn = make_row_classifier("nearest-neighbour");
  const auto train = two_classes(1000, 0, 3);
  nn->fit(train.rows, train.labels, 2);
  const double r = 1.0 - kBayes;
  const double a = accuracy(*nn, two_classes(2500, 0, 4));
  EXPECT_GE(a, 1.0 - 2.0 * r * (1.0 - r) - 0.02);
  EXPECT_LE(a, kBayes + 0.015);
}

TEST(RowClassifier, ScoresAreMinusHalfTheSquaredDistanceToTheNearestRow) {
  auto nn = make_row_classifier("nearest-neighbour");
  const std::vector<std::vector<double>> rows{{0, 0}, {2, 0}, {0, 2}, {2, 2}};
  const std::vector<int> labels{0, 0, 1, 1};
  nn->fit(rows, labels, 2);
  // Standardised by mean (1, 1) and sd sqrt(4/3) (n - 1 = 3): (1, 0) is at squared distance
  // 1 * 3/4 from (0,0) and (2,0), and (1 + 4) * 3/4 = 15/4 from (0,2) and (2,2).
  const auto s = nn->score(std::vector<double>{1.0, 0.0});
  EXPECT_NEAR(s.log_scores[0], -0.5 * 0.75, 1e-12);
  EXPECT_NEAR(s.log_scores[1], -0.5 * 3.75, 1e-12);
  EXPECT_NEAR(s.distances[0], std::sqrt(0.75), 1e-12);
  EXPECT_NEAR(s.distances[1], std::sqrt(3.75), 1e-12);
}

TEST(RowClassifier, AClassWithoutRowsAndUnknownNamesAreErrors) {
  auto lda = make_row_classifier("lda");
  const std::vector<std::vector<double>> rows{{0.0}, {1.0}};
  const std::vector<int> labels{0, 0};
  EXPECT_THROW(lda->fit(rows, labels, 2), InputError);
  EXPECT_THROW(make_row_classifier("svm"), InputError);
  EXPECT_EQ(row_classifier_names().front(), "lda");
  EXPECT_EQ(input_error_message([] { make_row_classifier("svm"); }),
            "unknown row classifier 'svm' (expected lda, lda-class-scaled, nearest-mean, "
            "nearest-neighbour, template, gaussian)");
}

TEST(RowClassifier, EveryNameBuildsAClassifierOfThatName) {
  for (const std::string& name : row_classifier_names())
    EXPECT_EQ(make_row_classifier(name)->name(), name);
}

// Rows the template classifier takes: whole onset windows (150 frames of 2 bands).
std::vector<std::vector<double>> windows(const TwoClasses& d) {
  std::vector<std::vector<double>> out;
  for (const auto& row : d.rows) out.emplace_back(300, row[0]);
  return out;
}

TEST(RowClassifier, EveryFitLoadsBackToTheSameScores) {
  const auto train = two_classes(20, 1, 5), test = two_classes(5, 1, 6);
  for (const std::string& name : row_classifier_names()) {
    auto c = make_row_classifier(name);
    const bool window = name == "template";
    c->fit(window ? windows(train) : train.rows, train.labels, 2);
    auto back = make_row_classifier(name);
    back->load(nlohmann::json::parse(c->save().dump()), "m.json");
    EXPECT_EQ(back->num_classes(), 2) << name;
    for (const auto& row : window ? windows(test) : test.rows) {
      const ClassScores a = c->score(row), b = back->score(row);
      EXPECT_EQ(a.log_scores, b.log_scores) << name;
      EXPECT_EQ(a.distances, b.distances) << name;
    }
  }
}

TEST(RowClassifier, AFitWithAMissingFieldIsAnInputError) {
  const auto train = two_classes(20, 1, 5);
  for (const char* name : {"lda", "nearest-neighbour"}) {
    auto c = make_row_classifier(name);
    c->fit(train.rows, train.labels, 2);
    nlohmann::json fit = c->save();
    fit.erase("scale");
    EXPECT_THROW(make_row_classifier(name)->load(fit, "m.json"), InputError) << name;
  }
}

}  // namespace
}  // namespace echoplan::perception
