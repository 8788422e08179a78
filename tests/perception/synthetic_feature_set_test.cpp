#include "perception/synthetic_feature_set.h"

#include <gtest/gtest.h>

#include <cmath>

#include "common/error.h"
#include "perception/feature_set.h"
#include "synthetic_feature_set.h"

namespace echoplan::perception {
namespace {

// The mean and variance of column j of a modality's rows.
std::pair<double, double> column_moments(const Modality& m, std::size_t j) {
  double sum = 0, sum2 = 0;
  for (const auto& row : m.rows) sum += row[j];
  const double mean = sum / static_cast<double>(m.rows.size());
  for (const auto& row : m.rows) sum2 += (row[j] - mean) * (row[j] - mean);
  return {mean, sum2 / static_cast<double>(m.rows.size() - 1)};
}

TEST(SyntheticFeatureSet, WritesTheShapeTheSpecAsks) {
  const auto dir = test_features::fresh_folder("synthetic_shape");
  SyntheticSpec spec;
  spec.objects = 6;
  spec.sessions = 3;
  spec.repeats = 2;
  spec.actions = {"press", "shake"};
  spec.modalities = {{"audio", 4, 2.0}, {"haptic", 2, 1.0}};
  spec.group_size = 3;
  write_synthetic_feature_set(dir, spec);
  const FeatureSet set = load_feature_set(dir.string());
  EXPECT_EQ(set.objects.size(), 6u);
  EXPECT_EQ(set.sessions.size(), 18u);
  ASSERT_EQ(set.actions.size(), 2u);
  for (const ActionData& a : set.actions) {
    EXPECT_EQ(a.rows.size(), 36u);  // 6 objects x 3 sessions x 2 repeats
    ASSERT_EQ(a.modalities.size(), 2u);
    EXPECT_EQ(a.modalities[0].feature_names.size(), 4u);  // audio (sorted by name)
    EXPECT_EQ(a.modalities[1].feature_names.size(), 2u);  // haptic
  }
  const ObjectGroups groups = load_groups((dir / "groups.csv").string());
  ASSERT_EQ(groups.groups.size(), 6u);
  EXPECT_EQ(groups.groups[2], "group0");
  EXPECT_EQ(groups.groups[3], "group1");
}

// With one object and no groups, a feature's variance over performances is
// (action scale x separation)^2 x 0 (one object mean, a constant) + session_sd^2 + 1, and its mean
// is scale x separation x O: a scale of 0 leaves pure standard-normal noise around 0.
TEST(SyntheticFeatureSet, AnActionScaleOfZeroIsPureNoise) {
  const auto dir = test_features::fresh_folder("synthetic_scale");
  SyntheticSpec spec;
  spec.objects = 40;
  spec.sessions = 50;
  spec.actions = {"mute", "loud"};
  spec.action_scales = {0.0, 1.0};
  spec.modalities = {{"audio", 3, 4.0}};
  write_synthetic_feature_set(dir, spec);
  const FeatureSet set = load_feature_set(dir.string());
  ASSERT_EQ(set.actions[1].name, "mute");  // sorted by name
  for (std::size_t j = 0; j < 3; ++j) {
    const auto [mean, variance] = column_moments(set.actions[1].modalities[0], j);
    EXPECT_NEAR(mean, 0.0, 0.15);      // 2000 standard normals: SE 0.022
    EXPECT_NEAR(variance, 1.0, 0.15);  // SE of the variance about 0.032
    // "loud": object means spread with SD 4 over 40 objects: variance about 17, far above 1.
    EXPECT_GT(column_moments(set.actions[0].modalities[0], j).second, 5.0);
  }
}

// Repeats share their session's offset: the difference of two repeats is noise only (variance 2),
// whatever session_sd is.
TEST(SyntheticFeatureSet, RepeatsShareTheirSessionOffset) {
  const auto dir = test_features::fresh_folder("synthetic_repeats");
  SyntheticSpec spec;
  spec.objects = 20;
  spec.sessions = 50;
  spec.repeats = 2;
  spec.session_sd = 5.0;
  spec.modalities = {{"audio", 1, 0.0}};
  write_synthetic_feature_set(dir, spec);
  const FeatureSet set = load_feature_set(dir.string());
  const Modality& m = set.actions[0].modalities[0];
  double within = 0, across = 0;
  const std::size_t pairs = m.rows.size() / 2;
  for (std::size_t i = 0; i < pairs; ++i) {
    within += std::pow(m.rows[2 * i][0] - m.rows[2 * i + 1][0], 2);
    if (i + 1 < pairs) across += std::pow(m.rows[2 * i][0] - m.rows[2 * i + 2][0], 2);
  }
  EXPECT_NEAR(within / static_cast<double>(pairs), 2.0, 0.3);  // 2 x noise variance
  // Consecutive sessions: 2 x (25 + 1) = 52.
  EXPECT_NEAR(across / static_cast<double>(pairs - 1), 52.0, 8.0);
}

// Per object, the mean of each feature over its rows of one action's only modality.
std::vector<std::vector<double>> object_means(const FeatureSet& set, const ActionData& action) {
  std::vector<std::vector<double>> sum(set.objects.size());
  std::vector<int> count(set.objects.size(), 0);
  const Modality& m = action.modalities[0];
  for (std::size_t i = 0; i < m.rows.size(); ++i) {
    const auto o = static_cast<std::size_t>(action.rows[i].object);
    sum[o].resize(m.rows[i].size(), 0.0);
    for (std::size_t j = 0; j < m.rows[i].size(); ++j) sum[o][j] += m.rows[i][j];
    ++count[o];
  }
  for (std::size_t o = 0; o < sum.size(); ++o)
    for (double& x : sum[o]) x /= count[o];
  return sum;
}

// With a pull of 1 and no object terms, an atypical object sits on its lookalike group's mean in
// every action: two objects are at one place (up to noise) exactly when they look alike, whatever
// their own groups.
TEST(SyntheticFeatureSet, AnAtypicalObjectLooksLikeTheSameOtherGroupInEveryAction) {
  const auto dir = test_features::fresh_folder("synthetic_atypical");
  SyntheticSpec spec;
  spec.objects = 12;
  spec.group_size = 3;
  spec.sessions = 100;
  spec.actions = {"press", "shake"};
  spec.modalities = {{"audio", 3, 0.0}};
  spec.group_separation = 4.0;
  spec.lookalike_share = 0.5;
  spec.lookalike_pull = 1.0;
  write_synthetic_feature_set(dir, spec);
  const std::vector<int> lookalike = synthetic_lookalikes(spec);
  int atypical = 0;
  for (int o = 0; o < spec.objects; ++o) atypical += lookalike[o] != o / spec.group_size;
  ASSERT_GT(atypical, 0);
  ASSERT_LT(atypical, spec.objects);
  const FeatureSet set = load_feature_set(dir.string());
  ASSERT_EQ(set.objects.size(), 12u);
  auto object_of = [&](std::size_t index) { return std::stoi(set.objects[index].substr(3)); };
  for (const ActionData& action : set.actions) {
    const auto means = object_means(set, action);
    for (std::size_t a = 0; a < means.size(); ++a)
      for (std::size_t b = a + 1; b < means.size(); ++b) {
        double distance2 = 0;
        for (std::size_t j = 0; j < 3; ++j) distance2 += std::pow(means[a][j] - means[b][j], 2);
        // Alike: noise only, 3 x 2 / 100 = 0.06 expected; apart: 3 x 2 x 16 = 96 expected.
        if (lookalike[object_of(a)] == lookalike[object_of(b)])
          EXPECT_LT(distance2, 0.5) << action.name << " " << set.objects[a] << set.objects[b];
        else
          EXPECT_GT(distance2, 2.0) << action.name << " " << set.objects[a] << set.objects[b];
      }
  }
}

TEST(SyntheticFeatureSet, RefusesASpecThatCannotMakeAFeatureSet) {
  const auto dir = test_features::fresh_folder("synthetic_bad");
  SyntheticSpec spec;
  spec.actions = {"a", "b"};
  spec.action_scales = {1.0};
  EXPECT_THROW(write_synthetic_feature_set(dir, spec), InputError);
  spec.action_scales.clear();
  spec.objects = 0;
  EXPECT_THROW(write_synthetic_feature_set(dir, spec), InputError);
  spec.objects = 4;
  spec.lookalike_share = 0.5;  // without groups an object has no other group to look like
  EXPECT_THROW(write_synthetic_feature_set(dir, spec), InputError);
  spec.group_size = 2;
  spec.lookalike_pull = 1.5;
  EXPECT_THROW(write_synthetic_feature_set(dir, spec), InputError);
}

}  // namespace
}  // namespace echoplan::perception
