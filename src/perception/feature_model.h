// An observation model fitted on a feature set's sessions: what the planner hears when the robot
// performs an action in a dataset trial, and the calibrated table P(symbol | class, action) it
// plans with (docs/feature-sets.md, "Fitting a model on a feature set").
//
// How it is fitted, on the training sessions only:
//  1. Per (action, modality), a classifier (feature_classifier.h: "lda" or "nearest-neighbour") on
//     the modality's rows, standardised with the training rows' means and deviations.
//  2. Inner cross-validation within the training sessions, with the task's own kind of hold-out
//     (make_folds on the training sessions): every training row gets held-out log-scores from
//     every modality's classifier.
//  3. Fusion (modality_fusion.h): the fused log-score of a class is sum_m w_m * score_m; the
//     weights w_m >= 0 minimise the held-out negative log-likelihood of the true classes under
//     softmax(fused), started from the best single modality with its temperature, so the fused
//     model is never worse on the inner folds than the best modality alone (and a pure-noise
//     modality gets a weight near 0, where equal weights would let it blur the informative one).
//  4. The table (observation_table.h): the counts of (true class, fused held-out decision),
//     shrunk by empirical Bayes towards a pooled structure (P(right), P(wrong, same bin), P(other
//     bin), estimated over all classes of the action); then tempered for repeated performances:
//     rows p^beta renormalised, beta in (0, 1] per action minimising the NLL of the true class
//     after each inner-held-out session's whole sequence of that action's observations (repeats of
//     one action on one object are correlated; the untempered iid product is overconfident), each
//     sequence scored with the table of the other inner folds' decisions.
// Symbols are the task's classes (no `unknown`: every trial's object is one of the set's).
#pragma once

#include <memory>
#include <span>
#include <string>
#include <vector>

#include "common/progress.h"
#include "perception/dataset_task.h"
#include "perception/feature_classifier.h"
#include "perception/feature_set.h"

namespace echoplan::perception {

struct FeatureModelFitter;

struct FeatureModelOptions {
  std::string classifier = std::string(kDefaultFeatureClassifier);  // feature_classifier_names()
};

// What inner cross-validation says about one action (for reports and the fusion claim).
struct ActionFit {
  std::string action;
  std::vector<std::string> modalities;    // the action's modalities, set order
  std::vector<double> modality_accuracy;  // held-out accuracy of each modality alone
  std::vector<double> modality_nll;       // its held-out mean NLL (temperature-calibrated)
  double fused_accuracy = 0.0;            // held-out accuracy of the fused decision
  double fused_nll = 0.0;                 // held-out mean NLL of the fused probabilities
  std::vector<double> weights;            // fusion weight per modality
  double shrinkage_strength = 0.0;        // empirical-Bayes prior count per table row
  double temper = 1.0;                    // beta: table rows are p^beta renormalised
};

// Fitted on some sessions; read-only after fitting, so it may be shared between threads.
class FeatureModel {
 public:
  // The set's actions, set order (the table's first index and classify's `action`).
  const std::vector<std::string>& actions() const { return actions_; }
  const std::vector<std::string>& classes() const { return classes_; }
  // The symbol (a class index) heard for row `row` of action `action` of `set` (a set with the
  // same actions and modalities, in the same order, as the one fitted on): the fused decision.
  int classify(int action, const FeatureSet& set, int row) const;
  // The fused, calibrated P(class | row) (softmax of the weighted log-scores).
  std::vector<double> probabilities(int action, const FeatureSet& set, int row) const;
  // [action][class][symbol]: the calibrated table (shrunk and tempered); rows sum to 1, entries >
  // 0.
  const std::vector<std::vector<std::vector<double>>>& table() const { return table_; }
  // Per action, the fused decision's inner cross-validated accuracy.
  std::vector<double> held_out_accuracy() const;
  // Per action, everything inner cross-validation measured.
  const std::vector<ActionFit>& fits() const { return fits_; }

 private:
  friend struct FeatureModelFitter;  // fit_feature_model's helper fills the fields
  std::vector<double> fused_scores(int action, const FeatureSet& set, int row) const;

  std::vector<std::string> actions_;
  std::vector<std::string> classes_;
  // [action][modality]: the classifier fitted on all training sessions.
  std::vector<std::vector<std::shared_ptr<const FeatureClassifier>>> classifiers_;
  std::vector<ActionFit> fits_;
  std::vector<std::vector<std::vector<double>>> table_;
};

// Fits on the rows of `training_sessions` (FeatureSet session indices). Throws InputError when
// the training sessions lack a class, or are too few for inner folds (make_folds' conditions).
// `progress` (optional) hears ("fit", actions done, actions).
FeatureModel fit_feature_model(const FeatureSet& set, const DatasetTask& task,
                               std::span<const int> training_sessions,
                               const FeatureModelOptions& options = {},
                               const ProgressFn& progress = {});

}  // namespace echoplan::perception
