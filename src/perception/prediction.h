// What the observation service reports for one heard clip.
#pragma once

#include <string>
#include <vector>

namespace echoplan::perception {

struct Prediction {
  std::string action;  // the sensing action the clip was recorded with
  // Index into ObservationModel::observation_symbols(): the class index, or classes().size() for
  // `unknown` (only when the model's reject option is on). This is the planner's observation.
  int symbol = 0;
  std::string label;     // the symbol's name: a class name or "unknown"
  bool unknown = false;  // the clip is further from every class than the reject threshold
  int best_class = 0;    // index of the most probable class, even when the clip is rejected
  // The confidence grade of the heard class (observation_grades.h: 0 = low), or -1 when the model
  // has no grades.
  int grade = -1;
  // The level grade of the recording (observation_grades.h, kind levels: 0 = noisy), or -1 when
  // the model has no level grades or the performance no measured level.
  int level_grade = -1;
  // Calibrated P(class | clip) over the model's classes (classes() order, sums to 1), assuming the
  // clip is one of them and all were equally likely before it was heard. Soft observations use
  // these.
  std::vector<double> probabilities;
  double distance = 0.0;  // the classifier's distance to the nearest class
  double reject_threshold =
      0.0;  // the distance above which a clip is unknown (infinity: reject off)
};

}  // namespace echoplan::perception
