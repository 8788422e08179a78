#include "perception/classifier.h"

#include <fmt/format.h>

#include <algorithm>

#include "common/error.h"
#include "perception/report_gaussian_classifier.h"
#include "perception/report_template_classifier.h"
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
  return {"summary-lda", "summary-nearest-mean", "report-template", "report-gaussian"};
}

const std::map<std::string, std::string>& classifier_aliases() {
  static const std::map<std::string, std::string> aliases{{"seed-gaussian", "report-gaussian"},
                                                          {"seed-template", "report-template"}};
  return aliases;
}

std::unique_ptr<Classifier> make_classifier(std::string_view name) {
  if (const auto alias = classifier_aliases().find(std::string(name));
      alias != classifier_aliases().end())
    name = alias->second;
  if (name == "summary-lda")
    return std::make_unique<SummaryLdaClassifier>(SummaryLdaClassifier::Covariance::ledoit_wolf);
  if (name == "summary-nearest-mean")
    return std::make_unique<SummaryLdaClassifier>(SummaryLdaClassifier::Covariance::identity);
  if (name == "report-template") return std::make_unique<ReportTemplateClassifier>();
  if (name == "report-gaussian") return std::make_unique<ReportGaussianClassifier>();
  throw InputError(fmt::format("unknown classifier '{}' (expected {})", name,
                               fmt::join(classifier_names(), ", ")));
}

}  // namespace echoplan::perception
