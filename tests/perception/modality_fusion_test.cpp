#include "perception/modality_fusion.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace echoplan::perception {
namespace {

// Held-out scores of 10 classes from two modalities: an informative one (the exact Gaussian
// log-likelihood of a 1-D feature with class means 0, 2, 4, ... and unit noise: a calibrated
// modality, weight 1), and a pure-noise one (log-likelihoods of 20 noise features under class
// means that were fitted on other noise: as large as the informative ones, and meaningless).
struct Data {
  ModalityScores scores{2};
  std::vector<int> labels;
};

Data informative_and_noise(int examples, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  constexpr int kClasses = 10, kNoise = 20;
  std::vector<std::vector<double>> noise_means(kClasses, std::vector<double>(kNoise));
  for (auto& m : noise_means)
    for (double& v : m) v = 0.5 * normal(rng);
  Data d;
  for (int i = 0; i < examples; ++i) {
    const int label = i % kClasses;
    const double x = 2.0 * label + normal(rng);
    std::vector<double> noise(kNoise);
    for (double& v : noise) v = normal(rng);
    std::vector<double> informative, meaningless;
    for (int c = 0; c < kClasses; ++c) {
      informative.push_back(-0.5 * (x - 2.0 * c) * (x - 2.0 * c));
      double sq = 0.0;
      for (int j = 0; j < kNoise; ++j)
        sq += (noise[j] - noise_means[c][j]) * (noise[j] - noise_means[c][j]);
      meaningless.push_back(-0.5 * sq);
    }
    d.scores[0].push_back(informative);
    d.scores[1].push_back(meaningless);
    d.labels.push_back(label);
  }
  return d;
}

double accuracy(const Data& d, const std::vector<double>& weights) {
  int right = 0;
  for (std::size_t i = 0; i < d.labels.size(); ++i) {
    const auto f = fuse({d.scores[0][i], d.scores[1][i]}, weights);
    right += std::max_element(f.begin(), f.end()) - f.begin() == d.labels[i];
  }
  return static_cast<double>(right) / static_cast<double>(d.labels.size());
}

TEST(ModalityFusion, FusedSumsWeightedScores) {
  const auto f = fuse({{1.0, 2.0}, {10.0, -10.0}}, std::vector<double>{2.0, 0.5});
  EXPECT_EQ(f, (std::vector<double>{7.0, -1.0}));
}

TEST(ModalityFusion, MeanNllOfTwoEqualScoresIsLogTwo) {
  const ModalityScores s{{{0.0, 0.0}}};
  const std::vector<int> labels{1};
  EXPECT_NEAR(fused_mean_nll(s, labels, std::vector<double>{1.0}), std::log(2.0), 1e-12);
}

TEST(ModalityFusion, ANoiseModalityGetsNoWeightWhereEqualWeightsAreVisiblyWorse) {
  const Data train = informative_and_noise(2000, 1), test = informative_and_noise(2000, 2);
  const Fusion fusion = fit_fusion(train.scores, train.labels);
  // The informative modality is calibrated as given (weight 1); the noise one is ignored.
  EXPECT_NEAR(fusion.weights[0], 1.0, 0.1);
  EXPECT_LT(fusion.weights[1], 0.02);
  // Never worse than the best single modality on the data it was fitted on.
  EXPECT_LE(fusion.mean_nll, fused_mean_nll(train.scores, train.labels, {1.0, 0.0}) + 1e-9);
  // On new data: the Bayes accuracy of the informative modality is 1 - 2 * 9/10 * Phi(-1) =
  // 0.714; naive equal weights lose much of it, and their NLL is far worse.
  const double bayes = 1.0 - 2.0 * 0.9 * 0.5 * std::erfc(1.0 / std::sqrt(2.0));
  EXPECT_NEAR(accuracy(test, fusion.weights), bayes, 0.03);
  EXPECT_LT(accuracy(test, {1.0, 1.0}), bayes - 0.15);
  EXPECT_GT(fused_mean_nll(test.scores, test.labels, {1.0, 1.0}),
            fused_mean_nll(test.scores, test.labels, fusion.weights) + 0.5);
}

TEST(ModalityFusion, TwoHalfInformativeModalitiesFuseBetterThanEither) {
  // Both modalities see the class through independent unit noise: the product (weights 1, 1) is
  // the Bayes rule, better than either alone.
  std::mt19937_64 rng(5);
  std::normal_distribution<double> normal(0.0, 1.0);
  ModalityScores s(2);
  std::vector<int> labels;
  for (int i = 0; i < 4000; ++i) {
    const int label = i % 5;
    for (auto& m : s) {
      const double x = 1.5 * label + normal(rng);
      std::vector<double> row;
      for (int c = 0; c < 5; ++c) row.push_back(-0.5 * (x - 1.5 * c) * (x - 1.5 * c));
      m.push_back(row);
    }
    labels.push_back(label);
  }
  const Fusion fusion = fit_fusion(s, labels);
  EXPECT_NEAR(fusion.weights[0], 1.0, 0.1);
  EXPECT_NEAR(fusion.weights[1], 1.0, 0.1);
  EXPECT_LT(fusion.mean_nll, fused_mean_nll(s, labels, {1.0, 0.0}) - 0.1);
}

}  // namespace
}  // namespace echoplan::perception
