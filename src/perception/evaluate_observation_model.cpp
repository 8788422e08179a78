#include "perception/evaluate_observation_model.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>

#include "common/error.h"

namespace echoplan::perception {

Evaluation evaluate_observation_model(const ObservationModel& model, const RecordingSet& set,
                                      const ProgressFn& progress) {
  for (const auto& action : set.actions)
    if (std::find(model.actions().begin(), model.actions().end(), action) == model.actions().end())
      throw InputError(
          set.root, 0,
          fmt::format("action '{}' of the recordings is not in the model (it was trained for: {})",
                      action, fmt::join(model.actions(), ", ")));
  Evaluation evaluation;
  const auto symbols = model.observation_symbols();
  ClipAnalyzer analyzer(model.analysis());
  ClipAnalysis analysis;
  int done = 0;
  for (const auto& action : model.actions()) {
    if (std::find(set.actions.begin(), set.actions.end(), action) == set.actions.end()) continue;
    ConfusionMatrix confusion = ConfusionMatrix::zeros(set.objects, symbols);
    for (const Recording* r : set.of_action(action)) {
      analyzer.analyse(read_recording(r->path, model.analysis().sample_rate), r->path, analysis);
      const Prediction p = model.classify(analysis, action);
      ++confusion.counts[static_cast<std::size_t>(set.object_index(r->object))]
                        [static_cast<std::size_t>(p.symbol)];
      if (progress) progress("evaluate", ++done, static_cast<int>(set.recordings.size()));
    }
    evaluation.per_action.push_back(std::move(confusion));
  }
  return evaluation;
}

}  // namespace echoplan::perception
