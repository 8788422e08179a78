#include "perception/heard_confusion.h"

#include "perception/train_observation_model.h"

namespace echoplan::perception {

std::vector<HeardConfusion> heard_confusion(const RecordingSet& set, const std::string& classifier,
                                            const AnalysisSettings& analysis,
                                            const ProgressFn& progress) {
  // Training cross-validates exactly this way (leave-one-out, every class a symbol when reject is
  // off); its calibration keeps the counts.
  TrainOptions options;
  options.classifier = classifier;
  options.analysis = analysis;
  options.reject = false;
  options.folds = 0;
  const ObservationModel model = train_observation_model(set, options, progress);
  std::vector<HeardConfusion> heard;
  for (const std::string& action : model.actions())
    heard.push_back({action, model.calibration(action).confusion});
  return heard;
}

}  // namespace echoplan::perception
