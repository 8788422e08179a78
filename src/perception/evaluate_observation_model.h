// Held-out evaluation of a trained observation model on a recording set it was not trained on.
#pragma once

#include <vector>

#include "common/progress.h"
#include "perception/calibration.h"
#include "perception/observation_model.h"
#include "perception/recording_set.h"

namespace echoplan::perception {

// Per action, the confusion of the set's objects against the model's observation symbols. Objects
// the model does not know are rows too (their correct report is `unknown`); accuracy() counts only
// the model's classes.
struct Evaluation {
  std::vector<ConfusionMatrix> per_action;  // model action order, actions present in the set
};

// Throws InputError if the set has an action the model was not trained for.
Evaluation evaluate_observation_model(const ObservationModel& model, const RecordingSet& set,
                                      const ProgressFn& progress = {});

}  // namespace echoplan::perception
