#include "perception/performance_reader.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "common/error.h"

namespace echoplan::perception {

PerformanceReader::PerformanceReader(const ObservationModel& model, const std::string& action,
                                     const FeatureSet& set)
    : model_(&model), model_action_(model.action_index(action)), data_(set.action(action)) {
  if (model_action_ < 0)
    throw InputError(set.root, 0,
                     fmt::format("the model has no action '{}' (it was trained for: {})", action,
                                 fmt::join(model.actions(), ", ")));
  if (data_ == nullptr)
    throw InputError(set.root, 0, fmt::format("the data has no action '{}'", action));
  for (const ModalityModel& m : model.modalities(action)) {
    const Modality* column = nullptr;
    for (const Modality& candidate : data_->modalities)
      if (candidate.name == m.name) column = &candidate;
    if (column == nullptr)
      throw InputError(
          set.root, 0,
          fmt::format("action '{}' has no modality '{}', which the model needs", action, m.name));
    // Rows of the same length may still be other features: a series binned by sums where the
    // model learnt means.
    if (column->series != m.series)
      throw InputError(
          set.root, 0,
          fmt::format("modality '{}' of '{}' was computed {} where the model's was {}: compute "
                      "the data's rows as the model's (--series {}={})",
                      m.name, action,
                      column->series.empty() ? "not from series" : "by " + column->series,
                      m.series.empty() ? "not computed from series" : "computed by " + m.series,
                      m.name, m.series.empty() ? "..." : m.series));
    columns_.push_back(column);
  }
}

Prediction PerformanceReader::classify(int row) const {
  std::vector<std::span<const double>> rows;
  for (const Modality* column : columns_)
    rows.emplace_back(column->rows.at(static_cast<std::size_t>(row)));
  return model_->classify_rows(model_action_, rows, level(row));
}

SeriesChoices series_choices(const ObservationModel& model) {
  SeriesChoices choices;
  for (const std::string& action : model.actions())
    for (const ModalityModel& m : model.modalities(action)) {
      if (m.series.empty()) continue;
      const auto [it, added] = choices.emplace(m.name, m.series);
      if (!added && it->second != m.series)
        throw InputError(
            fmt::format("the model computes modality '{}' as {} for one action and "
                        "as {} for another ('{}'): a recordings tree gives it one way",
                        m.name, it->second, m.series, action));
    }
  return choices;
}

int classify_row(const ObservationModel& model, int action, const FeatureSet& set, int row) {
  const ActionData& data = set.actions.at(static_cast<std::size_t>(action));
  std::vector<std::span<const double>> rows;
  for (const Modality& m : data.modalities)
    rows.emplace_back(m.rows.at(static_cast<std::size_t>(row)));
  return model.classify_rows(action, rows).best_class;
}

}  // namespace echoplan::perception
