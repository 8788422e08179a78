// make_classifier(): each name `echoplan train --classifier` accepts builds its classifier.
#include "perception/classifier.h"

#include <gtest/gtest.h>

#include <typeinfo>

#include "../common/input_error_message.h"
#include "perception/seed_gaussian_classifier.h"
#include "perception/seed_template_classifier.h"
#include "perception/summary_lda_classifier.h"

namespace echoplan::perception {
namespace {

TEST(Classifier, EveryNameBuildsItsClassifier) {
  EXPECT_EQ(classifier_names(), (std::vector<std::string>{"summary-lda", "summary-nearest-mean",
                                                          "seed-template", "seed-gaussian"}));
  const auto made = make_classifier("summary-lda");
  EXPECT_EQ(typeid(*made), typeid(SummaryLdaClassifier));
  const auto nearest_mean = make_classifier("summary-nearest-mean");
  EXPECT_EQ(typeid(*nearest_mean), typeid(SummaryLdaClassifier));
  const auto templates = make_classifier("seed-template");
  EXPECT_EQ(typeid(*templates), typeid(SeedTemplateClassifier));
  const auto gaussian = make_classifier("seed-gaussian");
  EXPECT_EQ(typeid(*gaussian), typeid(SeedGaussianClassifier));
}

TEST(Classifier, AnUnknownNameListsTheKnownOnes) {
  EXPECT_EQ(input_error_message([] { make_classifier("knn"); }),
            "unknown classifier 'knn' (expected summary-lda, summary-nearest-mean, seed-template, "
            "seed-gaussian)");
}

}  // namespace
}  // namespace echoplan::perception
