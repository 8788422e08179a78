// The one interface of echoplan's classifiers, and their registry by name.
//
// A row classifier is fitted on feature rows (vectors of one length) labelled with classes, and
// scores a new row against every class. Rows come from anywhere: a feature set's modality (any
// sensor), or a clip turned into a row by a named clip extractor (perception/clip_extractor.h; the
// audio presets of perception/classifier.h pair one with a row classifier). Scores become
// calibrated probabilities and a reject decision in the ObservationModel, so a classifier only has
// to say how alike the row is to each class, in two forms: log-scores (higher = more alike; their
// softmax after calibration is P(class | row)) and distances (>= 0, smaller = more alike; the
// distance to the nearest class decides whether a row is `unknown`).
//
// The registry (row_classifier_names()):
//   lda                 Gaussian classes, one shared covariance shrunk by Ledoit-Wolf; features
//                       standardised by the training rows' mean and deviation (lda_classifier.h)
//   lda-class-scaled    the same LDA, features scaled by their pooled within-class deviation
//                       (floored): the `summary-lda` audio preset
//   nearest-mean        class-scaled, identity covariance: Euclidean distance to each class mean
//   nearest-neighbour   the nearest standardised training row of each class (1-NN)
//   template            the report's templates: mean absolute difference to each class's mean
//                       onset-aligned log-filterbank window (report_template_classifier.h)
//   gaussian            the report's first classifier: a diagonal Gaussian per class over
//                       (centroid, rms) (report_gaussian_classifier.h)
#pragma once

#include <memory>
#include <nlohmann/json_fwd.hpp>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace echoplan::perception {

// How one row compares with each class; both vectors have one entry per class.
struct ClassScores {
  std::vector<double> log_scores;  // higher = more alike; differences are log-likelihood-like
  std::vector<double> distances;   // >= 0, in the classifier's own units; smaller = more alike

  // The class with the highest log-score (the first of equals).
  int best_class() const;
  // The distance to the nearest class.
  double nearest_distance() const;
};

class RowClassifier {
 public:
  virtual ~RowClassifier() = default;

  // The registry name ("lda", ...).
  virtual std::string name() const = 0;

  // Fits on rows[i] of class labels[i] in [0, num_classes); all rows the same length. Every class
  // needs a row (InputError otherwise). Refitting replaces the fit.
  virtual void fit(std::span<const std::vector<double>> rows, std::span<const int> labels,
                   int num_classes) = 0;

  // Classes of the current fit (0 before fit).
  virtual int num_classes() const = 0;

  // Scores a row against every class. Requires a fit; InputError for a row of the wrong length.
  virtual ClassScores score(std::span<const double> row) const = 0;

  // A new, unfitted classifier of the same kind and settings (cross-validation fits copies).
  virtual std::unique_ptr<RowClassifier> clone_unfitted() const = 0;

  // The fitted parameters as JSON (the model file's "classifier" object of a modality).
  virtual nlohmann::json save() const = 0;
  // Restores a fit written by save(). Throws InputError(source, 0, ...) naming the missing or
  // malformed field, e.g. "classifier.templates[2]: expected 150 x 26 numbers".
  virtual void load(const nlohmann::json& fit, const std::string& source) = 0;
};

// The row classifier feature sets use when none is named.
inline constexpr std::string_view kDefaultRowClassifier = "lda";

// Every registered name, default first.
std::vector<std::string> row_classifier_names();

// A new unfitted classifier; InputError listing the names for an unknown one.
std::unique_ptr<RowClassifier> make_row_classifier(std::string_view name);

}  // namespace echoplan::perception
