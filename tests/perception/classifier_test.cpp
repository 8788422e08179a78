// make_classifier(): each name `echoplan train --classifier` accepts builds its classifier.
#include "perception/classifier.h"

#include <gtest/gtest.h>

#include "../common/input_error_message.h"
#include "perception/seed_gaussian_classifier.h"
#include "perception/seed_template_classifier.h"
#include "perception/summary_lda_classifier.h"

namespace echoplan::perception {
namespace {

TEST(Classifier, EveryNameBuildsItsClassifier) {
  EXPECT_EQ(classifier_names(), (std::vector<std::string>{"summary-lda", "summary-nearest-mean",
                                                          "seed-template", "seed-gaussian"}));
  EXPECT_NE(dynamic_cast<SummaryLdaClassifier*>(make_classifier("summary-lda").get()), nullptr);
  EXPECT_NE(dynamic_cast<SummaryLdaClassifier*>(make_classifier("summary-nearest-mean").get()),
            nullptr);
  EXPECT_NE(dynamic_cast<SeedTemplateClassifier*>(make_classifier("seed-template").get()), nullptr);
  EXPECT_NE(dynamic_cast<SeedGaussianClassifier*>(make_classifier("seed-gaussian").get()), nullptr);
}

TEST(Classifier, AnUnknownNameListsTheKnownOnes) {
  EXPECT_EQ(input_error_message([] { make_classifier("knn"); }),
            "unknown classifier 'knn' (expected summary-lda, summary-nearest-mean, seed-template, "
            "seed-gaussian)");
}

}  // namespace
}  // namespace echoplan::perception
