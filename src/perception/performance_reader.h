// Reading a feature set's performances as a model sees them: a model fitted on one set classifies
// another set's rows (a replayed dataset world, `echoplan run --data`, held-out evaluation).
#pragma once

#include <vector>

#include "perception/feature_set.h"
#include "perception/observation_model.h"
#include "perception/recording_features.h"

namespace echoplan::perception {

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
  // The level measured from the row's recording (RowLabel::ebr_db), if it had one.
  std::optional<double> level(int row) const {
    return data_->rows.at(static_cast<std::size_t>(row)).ebr_db;
  }

 private:
  const ObservationModel* model_;
  int model_action_ = 0;
  const ActionData* data_ = nullptr;
  std::vector<const Modality*> columns_;  // [model modality] -> the set's modality
};

// The series features the model's modalities declare (ModalityModel::series), by modality: how a
// recordings tree must be turned into rows for the model to read it. InputError when two actions
// compute one modality differently (a tree gives each modality one way).
SeriesChoices series_choices(const ObservationModel& model);

// The model's fused decision on row `row` of the set's action `action` (a model fitted on `set`:
// the same actions and modalities in the same order).
int classify_row(const ObservationModel& model, int action, const FeatureSet& set, int row);

}  // namespace echoplan::perception
