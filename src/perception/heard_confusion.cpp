#include "perception/heard_confusion.h"

#include <algorithm>

#include "perception/evaluate_observation_model.h"
#include "perception/fit_observation_model.h"

namespace echoplan::perception {

namespace {

// Training cross-validates exactly this way (leave-one-out, every class a symbol when reject is
// off); its calibration keeps the counts, and the model itself is fitted on every recording.
ObservationModel leave_one_out(const RecordingSet& set, const std::string& classifier,
                               const AnalysisSettings& analysis, const ProgressFn& progress) {
  FitOptions options;
  options.classifier = classifier;
  options.analysis = analysis;
  options.reject = false;
  options.folds = 0;
  return train_observation_model(set, options, progress);
}

}  // namespace

std::vector<HeardConfusion> heard_confusion(const RecordingSet& set, const std::string& classifier,
                                            const AnalysisSettings& analysis,
                                            const ProgressFn& progress) {
  const ObservationModel model = leave_one_out(set, classifier, analysis, progress);
  std::vector<HeardConfusion> heard;
  for (const std::string& action : model.actions())
    heard.push_back({action, model.calibration(action).confusion});
  return heard;
}

std::vector<HeardConfusion> heard_confusion(const RecordingSet& set, const RecordingSet& variants,
                                            const std::string& classifier,
                                            const AnalysisSettings& analysis,
                                            const ProgressFn& progress) {
  const ObservationModel model = leave_one_out(set, classifier, analysis, progress);
  const Evaluation of_variants = evaluate_observation_model(model, variants, progress);
  std::vector<HeardConfusion> heard;
  std::size_t evaluated = 0;  // of_variants holds the model's actions that the variants have
  for (const std::string& action : model.actions()) {
    ConfusionMatrix confusion = model.calibration(action).confusion;
    if (std::find(variants.actions.begin(), variants.actions.end(), action) !=
        variants.actions.end()) {
      const ConfusionMatrix& v = of_variants.per_action.at(evaluated++);
      confusion.objects.insert(confusion.objects.end(), v.objects.begin(), v.objects.end());
      confusion.counts.insert(confusion.counts.end(), v.counts.begin(), v.counts.end());
    }
    heard.push_back({action, std::move(confusion)});
  }
  return heard;
}

}  // namespace echoplan::perception
