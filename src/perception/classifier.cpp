#include "perception/classifier.h"

#include <fmt/format.h>

#include <algorithm>

#include "common/error.h"
#include "perception/seed_gaussian_classifier.h"
#include "perception/seed_template_classifier.h"
#include "perception/summary_lda_classifier.h"

namespace echoplan::perception {

int ClassScores::best_class() const {
  return static_cast<int>(std::max_element(log_scores.begin(), log_scores.end()) -
                          log_scores.begin());
}

double ClassScores::nearest_distance() const {
  return *std::min_element(distances.begin(), distances.end());
}

std::vector<std::string> classifier_names() {
  return {"summary-lda", "summary-nearest-mean", "seed-template", "seed-gaussian"};
}

std::unique_ptr<Classifier> make_classifier(std::string_view name) {
  if (name == "summary-lda")
    return std::make_unique<SummaryLdaClassifier>(SummaryLdaClassifier::Covariance::ledoit_wolf);
  if (name == "summary-nearest-mean")
    return std::make_unique<SummaryLdaClassifier>(SummaryLdaClassifier::Covariance::identity);
  if (name == "seed-template") return std::make_unique<SeedTemplateClassifier>();
  if (name == "seed-gaussian") return std::make_unique<SeedGaussianClassifier>();
  throw InputError(fmt::format("unknown classifier '{}' (expected {})", name,
                               fmt::join(classifier_names(), ", ")));
}

}  // namespace echoplan::perception
