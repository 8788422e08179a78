// Training an observation model from recordings, with cross-validated calibration.
//
// Every recording is analysed once; per action, one classifier is cross-validated (leave-one-out,
// or k stratified folds) to get the confusion the classifier really makes. That confusion,
// Dirichlet-smoothed, is the planner's observation table; the same held-out scores calibrate the
// classifier's probabilities (temperature scaling) and set the reject threshold, beyond which a
// clip is reported as `unknown` instead of being forced into a class. The action's classifier is
// then fitted on all its recordings.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "common/progress.h"
#include "perception/observation_model.h"
#include "perception/recording_set.h"

namespace echoplan::perception {

struct TrainOptions {
  std::string classifier{kDefaultClassifier};  // make_classifier name
  AnalysisSettings analysis;
  bool reject = true;  // add the `unknown` symbol and its threshold
  // The reject threshold is this many times the largest held-out distance of a correctly classified
  // training clip to its own class: clips as far from every class as no training clip was are
  // unknown.
  double reject_margin = 1.5;
  double dirichlet_alpha = 1.0;  // pseudo-count added to every cell of each confusion row
  TableEstimate table = TableEstimate::counts;  // counts or soft (shrunk is fit_feature_model's)
  int folds = 0;                                // cross-validation folds; 0 = leave-one-out
  // Fold assignment when folds > 0: each action's shuffle draws from derive_seed(seed, {"fold",
  // stable_hash(action)}), the same on every platform.
  std::uint64_t seed = 0;
};

// The table estimates this recipe fits: counts and soft (shrunk is fit on sessions).
const std::vector<std::string>& clip_table_estimate_names();

// The cross-validation fold of each example of one action (labels[i] in [0, num_classes)):
// folds == 0 is leave-one-out (example i is fold i); otherwise stratified k folds, each class's
// examples shuffled and dealt round-robin. The shuffle draws from derive_seed(seed, {"fold",
// stable_hash(action)}): the same folds on every platform.
std::vector<int> cross_validation_folds(std::span<const int> labels, int num_classes, int folds,
                                        std::uint64_t seed, const std::string& action);

// Trains on every action of `set`. Throws InputError for unreadable recordings (naming the file),
// an unknown classifier, or options out of range.
ObservationModel train_observation_model(const RecordingSet& set, const TrainOptions& options,
                                         const ProgressFn& progress = {});

}  // namespace echoplan::perception
