// The observation service: turns a recording made during an action into an observation.
#pragma once

#include <map>
#include <optional>
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
  double probability = 0;  // calibrated probability of `label` (when unknown: of the nearest class)
  // The confidence grade of `label` (perception/observation_grades.h: 0 = low), or -1 when the
  // service does not grade: what a graded problem's symbol `<label>@<grade>` is made of.
  int grade = -1;
  // The level grade of the recording (kind levels: 0 = noisy), or -1: what a levels problem's
  // symbol `<label>@<level>` is made of.
  int level_grade = -1;
  std::vector<std::pair<std::string, double>> probabilities;  // per class, calibrated, sums to 1
  double distance = 0;  // the classifier's distance to the chosen class (for the reject option)
  // A few named numbers that describe the clip as the service analysed it (onset, level, ...), for
  // logs; may be empty.
  std::vector<std::pair<std::string, double>> features;
};

// What a service can report, known before any clip is heard; lets the loop check a service against
// the planner's problem before a trial starts.
struct ServiceVocabulary {
  // Per action it has a model for: the class names it reports.
  std::map<std::string, std::vector<std::string>> labels;
  bool may_report_unknown = false;  // the reject option is on
  bool grades = false;              // it grades what it hears (HeardObservation::grade)
  bool levels = false;              // it grades recordings by level (HeardObservation::level_grade)
};

class ObservationService {
 public:
  virtual ~ObservationService() = default;
  // What this service can report. The default, nothing, is for services that cannot tell in advance
  // (a remote classifier); the loop then checks each observation as it comes.
  virtual std::optional<ServiceVocabulary> vocabulary() const { return std::nullopt; }
  // Classifies `clip`, recorded during `action`. Throws InputError when the service has no model
  // for `action`.
  virtual HeardObservation observe(const audio::AudioClip& clip, const std::string& action) = 0;
};

}  // namespace echoplan::robot
