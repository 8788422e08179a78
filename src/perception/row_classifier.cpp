#include "perception/row_classifier.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>

#include "common/error.h"
#include "perception/lda_classifier.h"
#include "perception/nearest_neighbour_classifier.h"
#include "perception/report_gaussian_classifier.h"
#include "perception/report_template_classifier.h"

namespace echoplan::perception {

int ClassScores::best_class() const {
  return static_cast<int>(std::max_element(log_scores.begin(), log_scores.end()) -
                          log_scores.begin());
}

double ClassScores::nearest_distance() const {
  return *std::min_element(distances.begin(), distances.end());
}

std::vector<std::string> row_classifier_names() {
  return {"lda", "lda-class-scaled", "nearest-mean", "nearest-neighbour", "template", "gaussian"};
}

std::unique_ptr<RowClassifier> make_row_classifier(std::string_view name) {
  using Lda = LdaClassifier;
  if (name == "lda")
    return std::make_unique<Lda>(Lda::Scaling::standardise, Lda::Covariance::ledoit_wolf);
  if (name == "lda-class-scaled")
    return std::make_unique<Lda>(Lda::Scaling::class_scaled, Lda::Covariance::ledoit_wolf);
  if (name == "nearest-mean")
    return std::make_unique<Lda>(Lda::Scaling::class_scaled, Lda::Covariance::identity);
  if (name == "nearest-neighbour") return std::make_unique<NearestNeighbourClassifier>();
  if (name == "template") return std::make_unique<ReportTemplateClassifier>();
  if (name == "gaussian") return std::make_unique<ReportGaussianClassifier>();
  throw InputError(fmt::format("unknown row classifier '{}' (expected {})", name,
                               fmt::join(row_classifier_names(), ", ")));
}

}  // namespace echoplan::perception
