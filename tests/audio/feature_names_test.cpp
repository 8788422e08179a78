// Feature names as typed on the command line, and selecting one feature out of a Features.
#include <gtest/gtest.h>

#include <set>
#include <string_view>

#include "audio/features.h"
#include "test_signals.h"

namespace echoplan::audio {
namespace {

using testing::input_error_message;

constexpr FeatureKind kAll[] = {FeatureKind::log_mel,   FeatureKind::mfcc,    FeatureKind::centroid,
                                FeatureKind::bandwidth, FeatureKind::rolloff, FeatureKind::flatness,
                                FeatureKind::flux,      FeatureKind::rms,     FeatureKind::zcr};

TEST(FeatureNames, EveryKindHasADistinctNameThatReadsBack) {
  std::set<std::string_view> names;
  for (FeatureKind kind : kAll) {
    const std::string_view name = feature_name(kind);
    EXPECT_TRUE(names.insert(name).second) << name;
    EXPECT_EQ(feature_from_name(name), kind) << name;
  }
  EXPECT_EQ(feature_name(FeatureKind::log_mel), "logmel");
}

TEST(FeatureNames, UnknownNamesListTheKnownOnes) {
  const std::string message = input_error_message([] { feature_from_name("chroma"); });
  EXPECT_NE(message.find("unknown feature 'chroma'"), std::string::npos) << message;
  EXPECT_NE(message.find("logmel, mfcc"), std::string::npos) << message;
}

TEST(FeatureNames, SelectReturnsTheNamedMatrix) {
  Features f;
  for (FeatureKind kind : kAll) {
    EXPECT_EQ(&select_feature(f, kind), &select_feature(f, feature_from_name(feature_name(kind))));
  }
  EXPECT_EQ(&select_feature(f, FeatureKind::log_mel), &f.log_mel);
  EXPECT_EQ(&select_feature(f, FeatureKind::mfcc), &f.mfcc);
  EXPECT_EQ(&select_feature(f, FeatureKind::centroid), &f.centroid);
  EXPECT_EQ(&select_feature(f, FeatureKind::bandwidth), &f.bandwidth);
  EXPECT_EQ(&select_feature(f, FeatureKind::rolloff), &f.rolloff);
  EXPECT_EQ(&select_feature(f, FeatureKind::flatness), &f.flatness);
  EXPECT_EQ(&select_feature(f, FeatureKind::flux), &f.flux);
  EXPECT_EQ(&select_feature(f, FeatureKind::rms), &f.rms);
  EXPECT_EQ(&select_feature(f, FeatureKind::zcr), &f.zcr);
}

}  // namespace
}  // namespace echoplan::audio
