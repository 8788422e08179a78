// The observation model fitted on sessions: the recipe for recorded data, where a session (one
// exploration of one object) is the unit of cross-validation, an action may have several
// modalities, and repeats within a session are correlated (docs/feature-sets.md, "Fitting a model
// on a feature set"). The result is the one ObservationModel (observation_model.h): saved, loaded,
// replayed and run live like any other.
//
// How it is fitted, on the training sessions only:
//  1. Per (action, modality), a row classifier (row_classifier.h, "lda" by default) on the
//     modality's rows. A modality computed from clips (Modality::extractor) keeps its extractor,
//     so the model classifies live clips the same way.
//  2. Inner cross-validation within the training sessions, with the task's own kind of hold-out
//     (make_folds on the training sessions): every training row gets held-out log-scores from
//     every modality's classifier.
//  3. Fusion (modality_fusion.h): the fused log-score of a class is sum_m w_m * score_m; the
//     weights w_m >= 0 minimise the held-out negative log-likelihood of the true classes under
//     softmax(fused), started from the best single modality with its temperature, so the fused
//     model is never worse on the inner folds than the best modality alone (and a pure-noise
//     modality gets a weight near 0, where equal weights would let it blur the informative one).
//  4. The table (observation_table.h, TableEstimate::shrunk): the counts of (true class, fused
//  held-out
//     decision), shrunk by empirical Bayes towards a pooled structure (P(right), P(wrong, same
//     bin), P(other bin), estimated over all classes of the action); then tempered for repeated
//     performances: rows p^beta renormalised, beta in (0, 1] per action minimising the NLL of the
//     true class after each inner-held-out session's whole sequence of that action's observations
//     (repeats of one action on one object are correlated; the untempered iid product is
//     overconfident), each sequence scored with the table of the other inner folds' decisions.
// Symbols are the task's classes (no `unknown`: every trial's object is one of the set's); the
// temperature is 1 (the fusion weights carry it).
#pragma once

#include <span>
#include <string>
#include <vector>

#include "common/progress.h"
#include "perception/dataset_task.h"
#include "perception/feature_set.h"
#include "perception/observation_model.h"

namespace echoplan::perception {

struct FeatureModelOptions {
  std::string classifier = std::string(kDefaultRowClassifier);  // row_classifier_names()
};

// Fits on the rows of `training_sessions` (FeatureSet session indices). Throws InputError when
// the training sessions lack a class, or are too few for inner folds (make_folds' conditions).
// `progress` (optional) hears ("fit", actions done, actions).
ObservationModel fit_feature_model(const FeatureSet& set, const DatasetTask& task,
                                   std::span<const int> training_sessions,
                                   const FeatureModelOptions& options = {},
                                   const ProgressFn& progress = {});

// Reads the performances of one action of a feature set as one action of a model sees them: each
// modality of the model's action takes the set's modality of the same name (any order, extra ones
// ignored), so a model fitted on one set classifies another set's rows.
class PerformanceReader {
 public:
  // InputError (naming the set's folder) when the model has no such action, or the set's action
  // lacks a modality the model needs or gives it rows of another length.
  PerformanceReader(const ObservationModel& model, const std::string& action,
                    const FeatureSet& set);
  // What the model makes of row `row` of the set's action.
  Prediction classify(int row) const;

 private:
  const ObservationModel* model_;
  int model_action_ = 0;
  const ActionData* data_ = nullptr;
  std::vector<const Modality*> columns_;  // [model modality] -> the set's modality
};

// The model's fused decision on row `row` of the set's action `action` (a model fitted on `set`:
// the same actions and modalities in the same order).
int classify_row(const ObservationModel& model, int action, const FeatureSet& set, int row);

}  // namespace echoplan::perception
