// Classifiers on plain feature rows (a feature set's modality), for FeatureModel.
//
// The audio Classifier interface (classifier.h) embeds clips; feature-set rows are already
// vectors of any length, so these take rows directly. Both standardise each feature with the
// training rows' mean and standard deviation (a constant feature is divided by 1) so that
// features in different units weigh alike, and return one log-score per class (higher = more
// alike; softmax(log_scores / T) is a probability once the temperature T is fitted).
//  - "lda": Gaussian classes with one shared covariance, shrunk towards a multiple of the identity
//    by the Ledoit-Wolf estimate (SummaryLdaClassifier::ledoit_wolf: 50 features from a few
//    hundred rows need it). log-score = -Mahalanobis^2 / 2 to the class mean.
//  - "nearest-neighbour": the nearest training row of each class (1-NN decides by the best class,
//    as the datasets' reference results do). log-score = -distance^2 / 2 to the class's nearest
//    row. Suits classes made of several objects (a group held out by object), which are not one
//    Gaussian.
#pragma once

#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace echoplan::perception {

class FeatureClassifier {
 public:
  virtual ~FeatureClassifier() = default;
  virtual std::string name() const = 0;
  // rows[i] is of class labels[i] in [0, num_classes); all rows the same length; every class needs
  // a row (InputError otherwise).
  virtual void fit(std::span<const std::vector<double>> rows, std::span<const int> labels,
                   int num_classes) = 0;
  // One log-score per class. Requires a fit.
  virtual std::vector<double> log_scores(std::span<const double> row) const = 0;
  virtual std::unique_ptr<FeatureClassifier> clone_unfitted() const = 0;
};

inline constexpr std::string_view kDefaultFeatureClassifier = "lda";

// Every registered name, default first.
std::vector<std::string> feature_classifier_names();
// A new unfitted classifier; InputError listing the names for an unknown one.
std::unique_ptr<FeatureClassifier> make_feature_classifier(std::string_view name);

}  // namespace echoplan::perception
