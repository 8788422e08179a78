// make_classifier(): each audio preset `echoplan train --classifier` accepts pairs its clip
// extractor with its row classifier.
#include "perception/classifier.h"

#include <gtest/gtest.h>

#include <typeinfo>

#include "../common/input_error_message.h"
#include "common/error.h"
#include "perception/report_gaussian_classifier.h"
#include "perception/report_template_classifier.h"

namespace echoplan::perception {
namespace {

TEST(Classifier, EveryNameBuildsItsClassifier) {
  EXPECT_EQ(classifier_names(),
            (std::vector<std::string>{"summary-lda", "summary-nearest-mean", "report-template",
                                      "report-gaussian", "grid-lda", "pcen-lda"}));
  const std::map<std::string, std::pair<std::string, std::string>> parts{
      {"summary-lda", {"summary", "lda-class-scaled"}},
      {"summary-nearest-mean", {"summary", "nearest-mean"}},
      {"report-template", {"onset-logfbank", "template"}},
      {"report-gaussian", {"centroid-rms", "gaussian"}},
      {"grid-lda", {"spectrogram-grid", "lda-class-scaled"}},
      {"pcen-lda", {"pcen-summary", "lda-class-scaled"}}};
  for (const auto& [name, pair] : parts) {
    const auto made = make_classifier(name);
    ASSERT_NE(made->extractor(), nullptr);
    EXPECT_EQ(made->extractor()->name, pair.first) << name;
    EXPECT_EQ(made->rows().name(), pair.second) << name;
  }
  EXPECT_EQ(typeid(make_classifier("report-template")->rows()), typeid(ReportTemplateClassifier));
  EXPECT_EQ(typeid(make_classifier("report-gaussian")->rows()), typeid(ReportGaussianClassifier));
  for (const std::string& name : classifier_names()) EXPECT_EQ(make_classifier(name)->name(), name);
}

TEST(Classifier, OldNamesBuildTheRenamedClassifiers) {
  EXPECT_EQ(classifier_aliases(),
            (std::map<std::string, std::string>{{"seed-gaussian", "report-gaussian"},
                                                {"seed-template", "report-template"}}));
  const auto templates = make_classifier("seed-template");
  EXPECT_EQ(templates->rows().name(), "template");
  EXPECT_EQ(templates->name(), "report-template");
  const auto gaussian = make_classifier("seed-gaussian");
  EXPECT_EQ(gaussian->rows().name(), "gaussian");
  EXPECT_EQ(gaussian->name(), "report-gaussian");
}

TEST(Classifier, AnUnknownNameListsTheKnownOnes) {
  EXPECT_EQ(input_error_message([] { make_classifier("knn"); }),
            "unknown classifier 'knn' (expected summary-lda, summary-nearest-mean, "
            "report-template, report-gaussian, grid-lda, pcen-lda)");
}

TEST(Classifier, AModalityOfGivenRowsHasNoExtractorAndSaysSoWhenGivenAClip) {
  const auto haptic = make_modality_classifier("lda");
  EXPECT_EQ(haptic->name(), "lda");
  EXPECT_EQ(haptic->extractor(), nullptr);
  EXPECT_THROW(haptic->embed(ClipAnalysis{}), InputError);
  const auto audio = make_modality_classifier("nearest-neighbour", "summary");
  ASSERT_NE(audio->extractor(), nullptr);
  EXPECT_EQ(audio->extractor()->name, "summary");
  EXPECT_THROW(make_modality_classifier("lda", "mfcc"), InputError);
}

}  // namespace
}  // namespace echoplan::perception
