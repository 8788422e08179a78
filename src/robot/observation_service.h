// The observation service: turns a recording made during an action into an observation.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "audio/clip.h"

namespace echoplan::robot {

// What was heard, as the planner's observation. `label` is one of the service's class names, or
// "unknown" when the clip is unlike every class (the reject option).
struct HeardObservation {
  std::string label;
  bool unknown = false;
  double probability = 0;                                     // calibrated probability of `label`
  std::vector<std::pair<std::string, double>> probabilities;  // per class, calibrated, sums to 1
  double distance = 0;  // the classifier's distance to the chosen class (for the reject option)
};

class ObservationService {
 public:
  virtual ~ObservationService() = default;
  // Classifies `clip`, recorded during `action`. Throws InputError when the service has no model
  // for `action`.
  virtual HeardObservation observe(const audio::AudioClip& clip, const std::string& action) = 0;
};

}  // namespace echoplan::robot
