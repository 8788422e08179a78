// The trained observation model: one fitted classifier per sensing action, its calibration, and the
// table P(o | object, action) the planner plans with.
//
// This header holds the model and its classification. Training it (cross-validation and
// calibration) is train_observation_model.h, its JSON file observation_model_json.h, and held-out
// evaluation evaluate_observation_model.h; they are included at the end of this header so code that
// includes only this one keeps compiling.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "perception/calibration.h"
#include "perception/classifier.h"
#include "perception/clip_analysis.h"
#include "perception/prediction.h"

namespace echoplan::perception {

inline constexpr const char* kUnknownSymbol = "unknown";

// How the cross-validated decisions become the observation table (before Dirichlet smoothing).
//   counts: each held-out clip adds one to (its object, the symbol it was reported as).
//   soft:   each held-out clip adds its calibrated probabilities softmax(log_scores / T) to its
//           object's row (a rejected clip still adds its whole unit to `unknown`): the expected
//           confusion under the calibrated classifier, so an action that wins by narrow margins
//           gets a softer row than one that wins by wide margins.
enum class TableEstimate { counts, soft };
const char* table_estimate_name(TableEstimate estimate);
const std::vector<std::string>& table_estimate_names();
// Throws InputError("table estimate '<name>' is not one of: counts, soft").
TableEstimate parse_table_estimate(const std::string& name);

// What every action of a model shares: how clips are analysed, which classifier, what it reports.
struct ModelDescription {
  AnalysisSettings analysis;
  std::string classifier_name;       // make_classifier name
  std::vector<std::string> classes;  // the objects, in training-set order
  std::vector<std::string> actions;
  bool reject = true;  // the `unknown` symbol and a reject threshold per action
  double dirichlet_alpha = 1.0;
  TableEstimate table_estimate = TableEstimate::counts;
};

// Per action: what cross-validation measured and what the planner gets.
struct ActionCalibration {
  std::string action;
  double temperature = 1.0;
  double reject_threshold = 0.0;           // infinity when reject is off
  ConfusionMatrix confusion;               // cross-validated counts, objects x symbols
  std::vector<std::vector<double>> table;  // P(symbol | object), Dirichlet-smoothed confusion
                                           // (hard or soft, the model's table_estimate())
};

// One action's part of a model: its classifier, fitted on every recording of the action, and its
// calibration.
struct ActionModel {
  std::unique_ptr<Classifier> classifier;
  ActionCalibration calibration;
};

class ObservationModel {
 public:
  // An empty model (no classes, no actions), e.g. what an interrupted training returns.
  ObservationModel() = default;
  // `per_action` follows description.actions, each classifier fitted for description.classes.
  // Throws std::invalid_argument when they do not match (a programming error: training and the
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
  // classes() followed by "unknown" when reject() is on.
  std::vector<std::string> observation_symbols() const;
  // Calibration of `action`; throws InputError listing the actions for an unknown one.
  const ActionCalibration& calibration(const std::string& action) const;
  // The fitted classifier of `action` (InputError for an unknown one, as calibration()).
  const Classifier& classifier(const std::string& action) const;
  // P(symbol | object, action): classes().size() x observation_symbols().size().
  const std::vector<std::vector<double>>& observation_table(const std::string& action) const;

  // Classifies a clip recorded with `action`, already analysed with analysis() (a ClipAnalyzer
  // per thread; the model itself is read-only, so threads may share it).
  Prediction classify(const ClipAnalysis& analysed, const std::string& action) const;

 private:
  const ActionModel& of(const std::string& action) const;

  ModelDescription description_;
  std::vector<ActionModel> per_action_;  // description_.actions order
};

// Observation symbols of a description: its classes, then "unknown" when reject is on.
std::vector<std::string> observation_symbols(const ModelDescription& description);

}  // namespace echoplan::perception

// Forwarding includes: training, the model file and evaluation, for code that includes only this
// header (after the class, since each of them includes this header).
#include "perception/evaluate_observation_model.h"
#include "perception/observation_model_json.h"
#include "perception/train_observation_model.h"
