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
    const ConfusionMatrix zeros = ConfusionMatrix::zeros(set.objects, symbols);
    ConfusionMatrix confusion = zeros;
    const std::size_t index = evaluation.per_action.size();
    for (const Recording* r : set.of_action(action)) {
      analyzer.analyse(read_recording(r->path, model.analysis().sample_rate), r->path, analysis);
      const Prediction p = model.classify(analysis, action);
      const auto object = static_cast<std::size_t>(set.object_index(r->object));
      const auto symbol = static_cast<std::size_t>(p.symbol);
      ++confusion.counts[object][symbol];
      if (!r->surface.empty()) {
        std::vector<ConfusionMatrix>& on_table = evaluation.per_surface[r->surface];
        on_table.resize(index + 1, zeros);
        ++on_table[index].counts[object][symbol];
      }
      if (progress) progress("evaluate", ++done, static_cast<int>(set.recordings.size()));
    }
    evaluation.per_action.push_back(std::move(confusion));
    // A table with no recording of this action still has its (empty) matrix.
    for (auto& [table, matrices] : evaluation.per_surface) matrices.resize(index + 1, zeros);
  }
  return evaluation;
}

}  // namespace echoplan::perception
