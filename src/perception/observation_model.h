// The observation model, the one echoplan trains, saves, measures in campaigns and runs live: per
// sensing action, one fitted classifier per modality (audio computed from a clip by a clip
// extractor, or rows a sensor gives), their fusion weights and calibration, and the table
// P(o | object, action) the planner plans with.
//
// One pipeline fits it on any recorded data, a recordings tree or a feature set, its choices
// options (fit_observation_model.h); the result is this class and one file
// (observation_model_json.h).
//
// This header holds the model and its classification. Fitting it (cross-validation and
// calibration) is fit_observation_model.h, its JSON file observation_model_json.h, and held-out
// evaluation evaluate_observation_model.h; they are included at the end of this header so code that
// includes only this one keeps compiling.
#pragma once

#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "perception/calibration.h"
#include "perception/classifier.h"
#include "perception/clip_analysis.h"
#include "perception/observation_grades.h"
#include "perception/observation_table.h"
#include "perception/prediction.h"

namespace echoplan::perception {

inline constexpr const char* kUnknownSymbol = "unknown";

// What every action of a model shares: how clips are analysed, which classifier, what it reports.
struct ModelDescription {
  AnalysisSettings analysis;
  // The audio preset (make_classifier), or the row classifier of every modality of a model fitted
  // on sessions (make_modality_classifier).
  std::string classifier_name;
  std::vector<std::string> classes;  // the objects, in training-set order
  std::vector<std::string> actions;
  bool reject = true;  // the `unknown` symbol and a reject threshold per action
  double dirichlet_alpha = 1.0;
  TableEstimate table_estimate = TableEstimate::counts;
  // The share of objects that sound like another class (typicality.h, lookalikes), per kind: what
  // a dataset problem's lookalike copies start with. 0 (none) for a model cross-validated by
  // performance and in files without it.
  double lookalike_share = 0.0;
  double graded_lookalike_share = 0.0;
  // The share was fitted on the untempered tables, which a problem with lookalikes then plans
  // with (typicality.h, fit_lookalikes); false: on the tempered ones (and in files written before).
  bool lookalike_untempered = false;
  bool graded_lookalike_untempered = false;
};

// What cross-validation measured about one action: for reports and the fusion claim. Absent in
// model files written before every model had it.
struct ActionFit {
  std::vector<double> modality_accuracy;  // held-out accuracy of each modality alone
  std::vector<double> modality_nll;       // its held-out mean NLL (temperature-calibrated)
  double fused_accuracy = 0.0;            // held-out accuracy of the fused decision
  double fused_nll = 0.0;                 // held-out mean NLL of the fused probabilities
  double shrinkage_strength = 0.0;        // empirical-Bayes prior count per table row
  double temper = 1.0;                    // beta: table rows are p^beta renormalised
  double graded_temper = 1.0;             // the graded table's beta, fitted the same way
  double level_temper = 1.0;              // the levels table's beta, fitted the same way
};

// Per action: what cross-validation measured and what the planner gets.
struct ActionCalibration {
  std::string action;
  double temperature = 1.0;
  double reject_threshold = 0.0;           // infinity when reject is off
  ConfusionMatrix confusion;               // cross-validated counts, objects x symbols
  std::vector<std::vector<double>> table;  // P(symbol | object), the model's table_estimate()
  std::optional<ActionFit> fit;
  // Graded observations (observation_grades.h): the grades and P(graded symbol | object). Absent in
  // a model file written before grades existed: such a model serves labels only.
  std::optional<GradeCalibration> grades;
  std::vector<std::vector<double>> graded_table;
  // Observations of kind `levels`: the grades by measured event-to-background ratio and P(level
  // symbol | object). Absent when the training data had no measured levels (a feature set).
  std::optional<GradeCalibration> level_grades;
  std::vector<std::vector<double>> level_table;
};

// One sensor's part of an action: its name ("audio", "haptic", ...) and its fitted classifier.
struct ModalityModel {
  std::string name;
  std::shared_ptr<const Classifier> classifier;
  // The series features (signal/series_features.h spec) that turn this modality's series into a
  // row, or empty: rows computed from clips or given by a sensor.
  std::string series{};
};

// One action's part of a model: a classifier per modality, fitted on every training example of the
// action, the fusion weights and the calibration. Fused log-scores are sum_m weights[m] *
// score_m; P(class) = softmax(fused / temperature).
struct ActionModel {
  std::vector<ModalityModel> modalities;
  std::vector<double> weights;  // one per modality, >= 0
  ActionCalibration calibration;
};

class ObservationModel {
 public:
  // An empty model (no classes, no actions), e.g. what an interrupted training returns.
  ObservationModel() = default;
  // `per_action` follows description.actions, each classifier fitted for description.classes.
  // Throws std::invalid_argument when they do not match, or an action has no modality, a weight
  // per modality missing, or reject with several modalities (a programming error: training and the
  // model file check their input first).
  ObservationModel(ModelDescription description, std::vector<ActionModel> per_action);

  const ModelDescription& description() const { return description_; }
  const AnalysisSettings& analysis() const { return description_.analysis; }
  const std::string& classifier_name() const { return description_.classifier_name; }
  const std::vector<std::string>& classes() const { return description_.classes; }
  const std::vector<std::string>& actions() const { return description_.actions; }
  bool reject() const { return description_.reject; }
  double dirichlet_alpha() const { return description_.dirichlet_alpha; }
  TableEstimate table_estimate() const { return description_.table_estimate; }
  // The share of objects that sound like another class, for observations of `kind`.
  double lookalike_share(ObservationKind kind) const {
    // A levels problem's copies start with the labels' share (none is fitted for it).
    return kind == ObservationKind::graded ? description_.graded_lookalike_share
                                           : description_.lookalike_share;
  }
  // Whether a problem with lookalikes of `kind` mixes the untempered tables (levels: as the labels'
  // share, which its copies start with).
  bool lookalikes_untempered(ObservationKind kind) const {
    return kind == ObservationKind::graded ? description_.graded_lookalike_untempered
                                           : description_.lookalike_untempered;
  }
  // classes() followed by "unknown" when reject() is on.
  std::vector<std::string> observation_symbols() const;
  // Every action has graded observations (a model trained since they exist).
  bool graded() const;
  // Every action has observations graded by level (a model trained on recordings).
  bool levelled() const;
  // The symbols of `kind`: observation_symbols(), or graded_symbols(). InputError for graded or
  // levels when the model has no such grades.
  std::vector<std::string> observation_symbols(ObservationKind kind) const;
  // The index of what `heard` says among observation_symbols(kind).
  int symbol(const Prediction& heard, ObservationKind kind) const;
  // Calibration of `action`; throws InputError listing the actions for an unknown one.
  const ActionCalibration& calibration(const std::string& action) const;
  // The modalities of `action` (InputError for an unknown one, as calibration()).
  const std::vector<ModalityModel>& modalities(const std::string& action) const;
  // The fitted classifier of `action`'s first modality (an audio model's only one).
  const Classifier& classifier(const std::string& action) const;
  // The fusion weights of `action`, one per modality.
  const std::vector<double>& weights(const std::string& action) const;
  // The index of `action` in actions(), or -1.
  int action_index(const std::string& action) const;
  // P(symbol | object, action): classes().size() x observation_symbols().size().
  const std::vector<std::vector<double>>& observation_table(const std::string& action) const;
  // The same for `kind` (InputError for graded when the model has no grades).
  const std::vector<std::vector<double>>& observation_table(const std::string& action,
                                                            ObservationKind kind) const;
  // The same table before tempering for repeats (its rows' fitted power undone): what the
  // lookalike mixture mixes (typicality.h).
  std::vector<std::vector<double>> untempered_table(const std::string& action,
                                                    ObservationKind kind) const;

  // Classifies a clip recorded with `action`, already analysed with analysis() (a ClipAnalyzer
  // per thread; the model itself is read-only, so threads may share it). InputError when a
  // modality of the action is not computed from clips (its rows come from another sensor).
  Prediction classify(const ClipAnalysis& analysed, const std::string& action) const;
  // Classifies one performance of actions()[action] given as one row per modality, in
  // modalities() order, recorded at `ebr_db` when measured (its level grade; none: -1).
  // InputError for a missing row or one of the wrong length.
  Prediction classify_rows(int action, std::span<const std::span<const double>> rows,
                           std::optional<double> ebr_db = std::nullopt) const;

 private:
  const ActionModel& of(const std::string& action) const;
  Prediction predict(int action, const std::vector<ClassScores>& scores,
                     std::optional<double> ebr_db) const;

  ModelDescription description_;
  std::vector<ActionModel> per_action_;  // description_.actions order
};

// Observation symbols of a description: its classes, then "unknown" when reject is on.
std::vector<std::string> observation_symbols(const ModelDescription& description);

}  // namespace echoplan::perception

// Forwarding includes: training, the model file and evaluation, for code that includes only this
// header (after the class, since each of them includes this header).
#include "perception/evaluate_observation_model.h"
#include "perception/fit_observation_model.h"
#include "perception/observation_model_json.h"
