// The trained observation model: one classifier per sensing action, its calibration, and the table
// P(o | object, action) the planner plans with; saved as one JSON file.
//
// Training (train_observation_model) analyses every recording once, fits one classifier per action,
// and cross-validates it (leave-one-out, or k folds) to get the confusion the classifier really
// makes. That confusion, Dirichlet-smoothed, is the planner's observation table; the same held-out
// scores calibrate the classifier's probabilities (temperature scaling) and set the reject
// threshold, beyond which a clip is reported as `unknown` instead of being forced into a class.
//
// Model file (JSON, format "echoplan-observation-model", version 1):
//   { "format", "version", "analysis": {sample_rate, preset, onset {...}, silence_rms},
//     "classifier": name, "classes": [...], "actions": [...], "reject": bool, "dirichlet_alpha",
//     "table_estimate": "counts" | "soft" (absent in files written before it existed: "counts"),
//     "per_action": { action: { "classifier": {fit}, "temperature", "reject_threshold",
//                               "confusion": [[counts]], "symbols": [...], "table": [[P(o|k)]] } }
//                               }
// load_observation_model() checks every field and throws InputError naming the file and the field.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

#include "audio/clip.h"
#include "perception/calibration.h"
#include "perception/classifier.h"
#include "perception/clip_analysis.h"
#include "perception/prediction.h"
#include "perception/recording_set.h"

namespace echoplan::perception {

inline constexpr int kModelFormatVersion = 1;
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

struct TrainOptions {
  std::string classifier{kDefaultClassifier};  // make_classifier name
  AnalysisSettings analysis;
  bool reject = true;  // add the `unknown` symbol and its threshold
  // The reject threshold is this many times the largest held-out distance of a correctly classified
  // training clip to its own class: clips as far from every class as no training clip was are
  // unknown.
  double reject_margin = 1.5;
  double dirichlet_alpha = 1.0;  // pseudo-count added to every cell of each confusion row
  TableEstimate table = TableEstimate::counts;
  int folds = 0;           // cross-validation folds; 0 = leave-one-out
  std::uint64_t seed = 0;  // fold assignment when folds > 0
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

// Progress of long work: (what, done, total), e.g. ("analyse", 12, 80).
using ProgressFn = std::function<void(const std::string& stage, int done, int total)>;

class ObservationModel;

// Trains on every action of `set`. Throws InputError for unreadable recordings (naming the file),
// an unknown classifier, or options out of range.
ObservationModel train_observation_model(const RecordingSet& set, const TrainOptions& options,
                                         const ProgressFn& progress = {});

class ObservationModel {
 public:
  ObservationModel();
  ~ObservationModel();
  ObservationModel(ObservationModel&&) noexcept;
  ObservationModel& operator=(ObservationModel&&) noexcept;

  const AnalysisSettings& analysis() const;
  const std::string& classifier_name() const;
  const std::vector<std::string>& classes() const;  // the objects, in training-set order
  const std::vector<std::string>& actions() const;
  bool reject() const;
  TableEstimate table_estimate() const;
  // classes() followed by "unknown" when reject() is on.
  std::vector<std::string> observation_symbols() const;
  // Calibration of `action`; throws InputError listing the actions for an unknown one.
  const ActionCalibration& calibration(const std::string& action) const;
  // P(symbol | object, action): classes().size() x observation_symbols().size().
  const std::vector<std::vector<double>>& observation_table(const std::string& action) const;

  // Classifies a clip recorded with `action` (any rate and channel count). Thread-safe.
  Prediction classify(const audio::AudioClip& clip, const std::string& action) const;
  // Same, for a clip already analysed with analysis().
  Prediction classify(const ClipAnalysis& analysed, const std::string& action) const;

  nlohmann::json to_json() const;
  // Throws InputError(source, 0, "<field>: <problem>") for a malformed document or a wrong version.
  static ObservationModel from_json(const nlohmann::json& doc, const std::string& source);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  friend ObservationModel train_observation_model(const RecordingSet&, const TrainOptions&,
                                                  const ProgressFn&);
};

// Reads and writes the model file. Errors name the file: missing, not JSON (with the byte offset),
// truncated, wrong format or version, or a field out of shape.
ObservationModel load_observation_model(const std::string& path);
// Parses a model file's text; `source` names it in errors. What load_observation_model does after
// reading.
ObservationModel parse_observation_model(const std::string& text, const std::string& source);
void save_observation_model(const ObservationModel& model, const std::string& path);

// Held-out evaluation of a model on a recording set: per action, the confusion of the set's objects
// against the model's observation symbols. Objects the model does not know are rows too (their
// correct report is `unknown`); accuracy() counts only the model's classes.
struct Evaluation {
  std::vector<ConfusionMatrix> per_action;  // model action order, actions present in the set
};
// Throws InputError if the set has an action the model was not trained for.
Evaluation evaluate_observation_model(const ObservationModel& model, const RecordingSet& set,
                                      const ProgressFn& progress = {});

}  // namespace echoplan::perception
