// The default audio preset's parts: level-normalised summaries, Ledoit-Wolf and the one LDA.
#include "perception/lda_classifier.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <random>

#include "common/error.h"
#include "perception/ledoit_wolf.h"
#include "perception/summary_features.h"
#include "synthetic_sounds.h"

namespace echoplan::perception {
namespace {

using test_sounds::strike;
using test_sounds::three_objects;

std::vector<double> summary(const audio::AudioClip& clip) {
  ClipAnalyzer analyzer(AnalysisSettings{});
  ClipAnalysis a;
  analyzer.analyse(clip, "test", a);
  const auto s = summary_features(a);
  return {s.begin(), s.end()};
}

TEST(SummaryFeatures, IgnoreLevelAndLeadingSilence) {
  const auto& mug = three_objects()[1];
  const auto reference = summary(strike(mug, {.duration_s = 2.0, .onset_s = 0.5, .gain = 0.5}));
  // 20 dB softer, and 0.35 s of zeros with the strike later in the clip: the same summary (no
  // noise, so the only differences are rounding in the 16-bit-free float pipeline and the frame
  // grid).
  const auto soft = summary(strike(mug, {.duration_s = 2.0, .onset_s = 0.5, .gain = 0.05}));
  const auto late = summary(
      strike(mug, {.duration_s = 2.5, .leading_zeros_s = 0.35, .onset_s = 1.0, .gain = 0.5}));
  ASSERT_EQ(reference.size(), kSummarySize);
  ASSERT_EQ(summary_feature_names().size(), kSummarySize);
  for (std::size_t i = 0; i < kSummarySize; ++i) {
    EXPECT_NEAR(soft[i], reference[i], 1e-3) << summary_feature_names()[i];
    EXPECT_NEAR(late[i], reference[i], 1e-3) << summary_feature_names()[i];
  }
  // While another object's summary differs.
  const auto cup =
      summary(strike(three_objects()[0], {.duration_s = 2.0, .onset_s = 0.5, .gain = 0.5}));
  double difference = 0.0;
  for (std::size_t i = 0; i < kSummarySize; ++i) difference += std::abs(cup[i] - reference[i]);
  EXPECT_GT(difference / kSummarySize, 0.3);
}

TEST(LedoitWolf, MatchesTheClosedFormOnAKnownCase) {
  // Residual rows +-(1, 0) and +-(0, 3) (dof = n = 4): sample covariance diag(0.5, 4.5), mu = 2.5,
  // ||S - mu I||^2 = 8. Rank-one terms z z^T with z scaled by 1: diag(1, 0) or diag(0, 9); their
  // squared distances from S: 0.25 + 20.25 = 20.5 (twice) and 0.25 + 20.25 = 20.5 (twice): b^2 = 4
  // * 20.5 / 16.
  Eigen::MatrixXd r(4, 2);
  r << 1, 0, -1, 0, 0, 3, 0, -3;
  const auto [weight, covariance] = ledoit_wolf(r, 4.0);
  EXPECT_NEAR(weight, (4 * 20.5 / 16) / 8, 1e-12);
  EXPECT_NEAR(covariance(0, 0), (1 - weight) * 0.5 + weight * 2.5, 1e-12);
  EXPECT_NEAR(covariance(0, 1), 0.0, 1e-12);
}

// Embeddings of `per_class` recordings of each of the three synthetic objects, detuned per
// recording.
void examples(int per_class, unsigned seed, std::vector<std::vector<double>>& x,
              std::vector<int>& y) {
  for (int k = 0; k < 3; ++k)
    for (int i = 0; i < per_class; ++i) {
      const unsigned s = seed + static_cast<unsigned>(100 * k + i);
      std::mt19937 rng(s);
      const double gain = std::uniform_real_distribution<double>(0.1, 0.8)(rng);
      x.push_back(summary(strike(three_objects()[static_cast<std::size_t>(k)], {.duration_s = 1.6,
                                                                                .onset_s = 0.3,
                                                                                .gain = gain,
                                                                                .noise_rms = 0.0005,
                                                                                .detune = 0.02,
                                                                                .seed = s})));
      y.push_back(k);
    }
}

TEST(LdaClassScaled, ClassifiesHeldOutRecordingsAndSavesItsFit) {
  std::vector<std::vector<double>> train, test;
  std::vector<int> train_y, test_y;
  examples(3, 1, train, train_y);
  examples(2, 5000, test, test_y);
  using Lda = LdaClassifier;
  for (auto covariance : {Lda::Covariance::ledoit_wolf, Lda::Covariance::identity}) {
    Lda c(Lda::Scaling::class_scaled, covariance);
    c.fit(train, train_y, 3);
    EXPECT_GE(c.shrinkage(), 0.0);
    EXPECT_LE(c.shrinkage(), 1.0);
    for (std::size_t i = 0; i < test.size(); ++i) {
      const ClassScores s = c.score(test[i]);
      const auto best =
          std::min_element(s.distances.begin(), s.distances.end()) - s.distances.begin();
      EXPECT_EQ(best, test_y[i]) << c.name() << " test clip " << i;
    }
    Lda back(Lda::Scaling::class_scaled, covariance);
    back.load(c.save(), "m.json");
    const ClassScores a = c.score(test[0]), b = back.score(test[0]);
    for (std::size_t k = 0; k < 3; ++k) EXPECT_DOUBLE_EQ(a.distances[k], b.distances[k]);
  }
}

// Rows identical within each class (a deterministic sensor) have no spread to fit a metric on:
// the fit still succeeds and names each class's own row, whichever covariance it was asked for.
TEST(LdaClassScaled, RowsIdenticalWithinEachClassStillClassify) {
  const std::vector<std::vector<double>> rows = {{1, 5}, {1, 5}, {3, 2}, {3, 2}, {8, 8}, {8, 8}};
  const std::vector<int> labels = {0, 0, 1, 1, 2, 2};
  using Lda = LdaClassifier;
  for (auto scaling : {Lda::Scaling::class_scaled, Lda::Scaling::standardise}) {
    Lda c(scaling, Lda::Covariance::ledoit_wolf);
    ASSERT_NO_THROW(c.fit(rows, labels, 3));
    for (std::size_t i = 0; i < rows.size(); i += 2) {
      const ClassScores s = c.score(rows[i]);
      EXPECT_EQ(std::min_element(s.distances.begin(), s.distances.end()) - s.distances.begin(),
                labels[i]);
    }
  }
}

// The summary-lda preset's LDA fitted on two recordings of each synthetic object (`x`: the rows).
struct ClassScaledFit {
  std::vector<std::vector<double>> x;
  std::vector<int> y;
  LdaClassifier lda{LdaClassifier::Scaling::class_scaled, LdaClassifier::Covariance::ledoit_wolf};
  ClassScaledFit() {
    examples(2, 1, x, y);
    lda.fit(x, y, 3);
  }
};

TEST(LdaClassScaled, LoadRejectsMalformedFits) {
  const ClassScaledFit fit;
  using Lda = LdaClassifier;
  const Lda& c = fit.lda;
  const nlohmann::json good = c.save();
  Lda back(Lda::Scaling::class_scaled, Lda::Covariance::ledoit_wolf);
  nlohmann::json bad = good;
  bad["scale"][0] = -1.0;
  EXPECT_THROW(back.load(bad, "m.json"), InputError);
  bad = good;
  bad["whitening"][0][5] = 1.0;  // above the diagonal
  EXPECT_THROW(back.load(bad, "m.json"), InputError);
  bad = good;
  bad["features"] = 12;  // the vectors hold 123
  EXPECT_THROW(back.load(bad, "m.json"), InputError);
  bad = good;
  bad["mean"] = std::vector<double>(5, 0.0);
  EXPECT_THROW(back.load(bad, "m.json"), InputError);
  bad = good;
  bad.erase("class_means");
  EXPECT_THROW(back.load(bad, "m.json"), InputError);
  EXPECT_THROW(c.score(std::vector<double>(5, 0.0)), InputError);
}

// A fit as model format 1 wrote it (summary_size, no mean) scores exactly as the fit it came from.
TEST(LdaClassScaled, LoadsTheFormatOneFit) {
  const ClassScaledFit fit;
  using Lda = LdaClassifier;
  const Lda& c = fit.lda;
  const auto& x = fit.x;
  nlohmann::json old = c.save();
  for (double m : old["mean"].get<std::vector<double>>()) ASSERT_EQ(m, 0.0);
  old["summary_size"] = old["features"];
  old.erase("features");
  old.erase("mean");
  Lda back(Lda::Scaling::class_scaled, Lda::Covariance::ledoit_wolf);
  back.load(old, "old.json");
  EXPECT_EQ(back.score(x[4]).log_scores, c.score(x[4]).log_scores);
}

}  // namespace
}  // namespace echoplan::perception
