// Held-out evaluation of a trained observation model on a recording set it was not trained on.
#pragma once

#include <map>
#include <string>
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
  // A set whose manifest names each recording's table (Recording::surface): per table, the same
  // confusions of its recordings alone (they add up to per_action); empty otherwise.
  std::map<std::string, std::vector<ConfusionMatrix>> per_surface;
};

// Throws InputError if the set has an action the model was not trained for.
Evaluation evaluate_observation_model(const ObservationModel& model, const RecordingSet& set,
                                      const ProgressFn& progress = {});

}  // namespace echoplan::perception
