// make_classifier(): each name `echoplan train --classifier` accepts builds its classifier.
#include "perception/classifier.h"

#include <gtest/gtest.h>

#include <typeinfo>

#include "../common/input_error_message.h"
#include "perception/report_gaussian_classifier.h"
#include "perception/report_template_classifier.h"
#include "perception/summary_lda_classifier.h"

namespace echoplan::perception {
namespace {

TEST(Classifier, EveryNameBuildsItsClassifier) {
  EXPECT_EQ(classifier_names(), (std::vector<std::string>{"summary-lda", "summary-nearest-mean",
                                                          "report-template", "report-gaussian"}));
  const auto made = make_classifier("summary-lda");
  EXPECT_EQ(typeid(*made), typeid(SummaryLdaClassifier));
  const auto nearest_mean = make_classifier("summary-nearest-mean");
  EXPECT_EQ(typeid(*nearest_mean), typeid(SummaryLdaClassifier));
  const auto templates = make_classifier("report-template");
  EXPECT_EQ(typeid(*templates), typeid(ReportTemplateClassifier));
  const auto gaussian = make_classifier("report-gaussian");
  EXPECT_EQ(typeid(*gaussian), typeid(ReportGaussianClassifier));
  for (const std::string& name : classifier_names()) EXPECT_EQ(make_classifier(name)->name(), name);
}

TEST(Classifier, OldNamesBuildTheRenamedClassifiers) {
  EXPECT_EQ(classifier_aliases(),
            (std::map<std::string, std::string>{{"seed-gaussian", "report-gaussian"},
                                                {"seed-template", "report-template"}}));
  const auto templates = make_classifier("seed-template");
  EXPECT_EQ(typeid(*templates), typeid(ReportTemplateClassifier));
  EXPECT_EQ(templates->name(), "report-template");
  const auto gaussian = make_classifier("seed-gaussian");
  EXPECT_EQ(typeid(*gaussian), typeid(ReportGaussianClassifier));
  EXPECT_EQ(gaussian->name(), "report-gaussian");
}

TEST(Classifier, AnUnknownNameListsTheKnownOnes) {
  EXPECT_EQ(input_error_message([] { make_classifier("knn"); }),
            "unknown classifier 'knn' (expected summary-lda, summary-nearest-mean, "
            "report-template, report-gaussian)");
}

}  // namespace
}  // namespace echoplan::perception
