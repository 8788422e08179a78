// What a classifier hears in a recording set: per sensing action, the leave-one-out confusion of
// the set's objects (each recording classified by the classifier fitted on every other recording of
// its action), with no reject option. The report's own measure of how well its classifier heard
// (the behavioural realism measure; bench/sim_heard.py measures the same through `echoplan train
// --folds 0 --no-reject`), shown on the chapter-5 page beside the lab's counts.
#pragma once

#include <string>
#include <vector>

#include "common/progress.h"
#include "perception/calibration.h"
#include "perception/clip_analysis.h"
#include "perception/recording_set.h"

namespace echoplan::perception {

// One action's heard confusion: rows the set's objects, columns the classes heard (the same
// objects), counts of recordings.
struct HeardConfusion {
  std::string action;
  ConfusionMatrix confusion;
};

// Per action of `set`, in the set's order, the leave-one-out confusion of `classifier` (a
// make_classifier name). Throws InputError for unreadable recordings or an unknown classifier.
std::vector<HeardConfusion> heard_confusion(const RecordingSet& set, const std::string& classifier,
                                            const AnalysisSettings& analysis = {},
                                            const ProgressFn& progress = {});

// The same, with the recordings of `variants` (objects that are no class: a modified object) heard
// by the classifier fitted on all of `set`, as the report heard its weighted objects with templates
// made from the originals: their rows follow the set's in each action's confusion. `variants` must
// have only actions of `set` (InputError naming it otherwise).
std::vector<HeardConfusion> heard_confusion(const RecordingSet& set, const RecordingSet& variants,
                                            const std::string& classifier,
                                            const AnalysisSettings& analysis = {},
                                            const ProgressFn& progress = {});

}  // namespace echoplan::perception
