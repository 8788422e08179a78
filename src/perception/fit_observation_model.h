// Fitting the one observation model (observation_model.h) on recorded data: one pipeline for every
// kind of data. A recordings tree is a feature set whose modality "audio" is computed from each
// clip by a clip extractor (recording_features.h), each clip one performance; a feature set gives
// any sensors' rows. Either way, per sensing action, on the training sessions only:
//  1. A classifier per modality (classifier.h: an audio preset over clips, or a row classifier),
//     cross-validated: by performance (leave-one-out, or k folds stratified by class) or by session
//     with the task's own kind of hold-out (make_folds on the training sessions), so every training
//     row gets held-out log-scores from every modality.
//  2. Probabilities: one temperature on the modalities' summed log-scores (fit_temperature, with
//  the
//     Dirichlet prior's share of a row as label smoothing, so the probabilities are no surer than
//     the smoothed table), or fusion weights (modality_fusion.h: a weight per modality, never worse
//     on the held-out scores than the best modality alone).
//  3. The reject option (one modality only): a held-out performance farther from every class than
//     reject_margin times the largest distance of a correctly classified one is `unknown`.
//  4. The table (observation_table.h) from the held-out decisions: counts or soft, smoothed with a
//     Dirichlet prior, or shrunk by empirical Bayes towards a pooled structure of the task's bins.
//  5. Grades (observation_grades.h): the calibrated probability of the class each performance was
//     heard as, in three grades, and the graded table.
//  6. With cross-validation by session: tempering for repeats (rows p^beta, beta fitted on each
//     inner-held-out session's sequences of one action, each scored with the table of the other
//     inner folds), if asked, and the share of lookalikes (typicality.h), always. Both are about
//     how a session's performances err together, so they need the folds every action shares.
// Then each modality's classifier is fitted on every training row of its action.
//
// Defaults by kind of data, and why:
//  - recordings (FitOptions{}): the report's setting, a few clips per object and action, one
//    modality. Leave-one-out uses every clip; counts smoothed by Laplace's rule keep a row from few
//    clips free of zeros; the reject option says `unknown` for a clip unlike any it was trained on
//    (nothing was struck); one modality needs no fusion; clips are separate performances, so no
//    tempering.
//  - feature sets (session_fit_options()): many objects, several sensors, a few sessions of
//    repeated behaviours. Folds by session keep a session's correlated repeats out of the rows they
//    are judged with; fusion weighs the sensors; the shrunk table learns 100 classes from a few
//    rows each; tempering stops repeats from counting as independent; a trial's object is always
//    one of the set's classes, so no reject.
// Every option is open to every kind of data (`echoplan train --help` lists them); the checks
// below refuse only combinations that have no meaning.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "common/progress.h"
#include "perception/dataset_task.h"
#include "perception/feature_set.h"
#include "perception/observation_model.h"
#include "perception/recording_features.h"
#include "perception/recording_set.h"

namespace echoplan::perception {

// How held-out decisions are made.
enum class CrossValidation {
  by_performance,  // leave-one-out (folds 0) or k folds stratified by class, per action
  by_session,      // the task's folds over the training sessions (make_folds), shared by actions
  // A recordings tree made on several tables (its manifest's `surface` column): each table held
  // out in turn, its recordings the sessions (sessions_by_surface), so the table and grades say
  // what a table the model never heard does to its readings; by session otherwise.
  by_surface,
};
const char* cross_validation_name(CrossValidation cv);  // "performance", "session" or "surface"
// InputError naming both for anything else.
CrossValidation parse_cross_validation(const std::string& name);

struct FitOptions {
  // An audio preset (make_classifier: its clip extractor computes a recordings tree's audio rows),
  // or a row classifier (row_classifier_names(): for rows a sensor gave, or audio rows computed by
  // the default "summary" extractor).
  std::string classifier{kDefaultClassifier};
  AnalysisSettings analysis;  // how a recordings tree's clips are analysed (and live ones)
  SeriesChoices series;       // how a recordings tree's series become rows (recording_features.h)
  CrossValidation cross_validation = CrossValidation::by_performance;
  int folds = 0;           // by performance: 0 = leave-one-out, else at least 2
  std::uint64_t seed = 0;  // by performance with folds > 0: the shuffle (cross_validation_folds)
  bool fuse = false;       // fusion weights instead of one temperature
  bool reject = true;      // the `unknown` symbol and its threshold (one modality per action)
  double reject_margin = 1.5;
  double dirichlet_alpha = 1.0;  // counts and soft: the pseudo-count added to every cell
  TableEstimate table = TableEstimate::counts;
  bool temper = false;  // temper the tables for repeats (cross-validation by session)
};

// The defaults for a feature set (above): folds by session, fusion, the shrunk table tempered for
// repeats, no reject, no Dirichlet prior; `classifier` a row classifier.
FitOptions session_fit_options(std::string classifier = std::string(kDefaultRowClassifier));

// The options a user names (`echoplan train`'s flags, Python's fit_observation_model keywords);
// absent: the default.
struct FitChoices {
  std::optional<std::string> cross_validation, classifier, table;
  std::optional<int> folds, sample_rate;
  std::optional<std::uint64_t> seed;
  std::optional<bool> reject, fuse, temper;
  std::optional<double> reject_margin, alpha;
  SeriesChoices series;  // empty: every series by signal::kDefaultSeriesFeatures
};

// The defaults of the cross-validation, FitOptions{} or session_fit_options(), then every choice
// made. The cross-validation is the one named, else by session for a feature set or when the task
// is named (groups or a hold-out), by performance for a recordings tree. Data of several
// modalities per action (a recordings tree with series) has no reject option unless it is chosen
// (it needs one modality). InputError for a bad name, series chosen for a feature set, or as
// check_fit_options.
FitOptions choose_fit_options(const FitChoices& choices, DataKind kind, bool task_named,
                              bool several_modalities = false);

// InputError naming the option for values out of range or combinations without meaning: folds 1
// or negative; a margin outside 1..100 or alpha outside 0..1000; tempering without folds by
// session; the shrunk table with the reject option (its pooled structure has no `unknown`).
void check_fit_options(const FitOptions& options);

// The cross-validation fold of each example of one action (labels[i] in [0, num_classes)):
// folds == 0 is leave-one-out (example i is fold i); otherwise stratified k folds, each class's
// examples shuffled and dealt round-robin. The shuffle draws from derive_seed(seed, {"fold",
// stable_hash(action)}): the same folds on every platform.
std::vector<int> cross_validation_folds(std::span<const int> labels, int num_classes, int folds,
                                        std::uint64_t seed, const std::string& action);

// Fits on the rows of `training_sessions` (FeatureSet session indices) of every action of `set`;
// classes are the task's. InputError for bad options (check_fit_options), an audio preset on rows
// its extractor did not compute, the reject option on an action of several modalities, a class
// without training rows, or too few of them for the folds (fewer than 2 performances of a class in
// an action by performance; make_folds' conditions by session). `progress` (optional) hears
// ("fit", actions done, actions).
ObservationModel fit_observation_model(const FeatureSet& set, const DatasetTask& task,
                                       std::span<const int> training_sessions,
                                       const FitOptions& options, const ProgressFn& progress = {});

// A recordings tree as the data the options fit: its clips analysed with options.analysis and
// turned into rows by the options' classifier's clip extractor (an audio preset's own; "summary"
// for a row classifier), as feature_set_from_recordings does. InputError naming an unreadable
// recording; `progress` hears ("analyse", done, total).
FeatureSet recordings_as_features(const RecordingSet& set, const FitOptions& options,
                                  const ProgressFn& progress = {});

// A recordings tree fitted on every clip (recordings_as_features), classes its objects. InputError
// as recordings_as_features and fit_observation_model.
ObservationModel train_observation_model(const RecordingSet& set, const FitOptions& options,
                                         const ProgressFn& progress = {});

}  // namespace echoplan::perception
