// The interface every observation classifier implements, and the registry of classifiers by name.
//
// A classifier turns each analysed clip into a fixed-length embedding (its own features), is fitted
// on the embeddings of one sensing action's recordings (one classifier per action), and then scores
// a new clip against every class. Scores are turned into calibrated probabilities and a reject
// decision by the ObservationModel (perception/observation_model.h), so a classifier only has to
// say how alike the clip is to each class, in two forms: log-scores (higher = more alike; their
// softmax after temperature calibration is P(class | clip)) and distances (>= 0, smaller = more
// alike; the distance to the nearest class decides whether a clip is `unknown`).
#pragma once

#include <map>
#include <memory>
#include <nlohmann/json_fwd.hpp>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "perception/clip_analysis.h"

namespace echoplan::perception {

// How one clip compares with each class; both vectors have one entry per class.
struct ClassScores {
  std::vector<double> log_scores;  // higher = more alike; differences are log-likelihood-like
  std::vector<double> distances;   // >= 0, in the classifier's own units; smaller = more alike

  // The class with the highest log-score (the first of equals).
  int best_class() const;
  // The distance to the nearest class.
  double nearest_distance() const;
};

class Classifier {
 public:
  virtual ~Classifier() = default;

  // The registry name ("report-template", ...).
  virtual std::string name() const = 0;

  // The fixed-length vector this classifier compares: its own features of one analysed clip (a pure
  // function of the clip, so training computes it once per recording and cross-validation reuses
  // it).
  virtual std::vector<double> embed(const ClipAnalysis& clip) const = 0;

  // Fits on embeddings of clips of one action: examples[i] is a recording of class labels[i] in
  // [0, num_classes). Every class needs at least one example (throws InputError otherwise).
  // Refitting replaces the fit.
  virtual void fit(std::span<const std::vector<double>> examples, std::span<const int> labels,
                   int num_classes) = 0;

  // Classes of the current fit (0 before fit).
  virtual int num_classes() const = 0;

  // Scores an embedding against every class. Requires a fit; throws InputError for an embedding of
  // the wrong length.
  virtual ClassScores score(std::span<const double> embedding) const = 0;

  // score(embed(clip)).
  ClassScores score_clip(const ClipAnalysis& clip) const { return score(embed(clip)); }

  // A new, unfitted classifier of the same kind and settings (cross-validation fits copies).
  virtual std::unique_ptr<Classifier> clone_unfitted() const = 0;

  // The fitted parameters as JSON (the model file's per-action "classifier" object, without its
  // name).
  virtual nlohmann::json save() const = 0;
  // Restores a fit written by save(). Throws InputError(source, 0, ...) naming the missing or
  // malformed field, e.g. "classifier.templates[2]: expected 150 x 26 numbers".
  virtual void load(const nlohmann::json& fit, const std::string& source) = 0;
};

// The classifier the commands use when none is named.
inline constexpr std::string_view kDefaultClassifier = "summary-lda";

// Names of every registered classifier, default first.
std::vector<std::string> classifier_names();

// Earlier names of registered classifiers, each with its current name: "seed-template" and
// "seed-gaussian" (the report's two classifiers, named before "seed" was kept for random seeds).
// Model files, campaign files and scripts written with them keep working.
const std::map<std::string, std::string>& classifier_aliases();

// A new unfitted classifier, by current name or alias (its name() is always the current one).
// Throws InputError listing the names for an unknown one.
std::unique_ptr<Classifier> make_classifier(std::string_view name);

}  // namespace echoplan::perception
