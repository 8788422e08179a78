#include "perception/observation_model.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <stdexcept>

#include "common/error.h"

namespace echoplan::perception {

const char* table_estimate_name(TableEstimate estimate) {
  return estimate == TableEstimate::soft ? "soft" : "counts";
}

const std::vector<std::string>& table_estimate_names() {
  static const std::vector<std::string> names{"counts", "soft"};
  return names;
}

TableEstimate parse_table_estimate(const std::string& name) {
  if (name == "counts") return TableEstimate::counts;
  if (name == "soft") return TableEstimate::soft;
  throw InputError(fmt::format("table estimate '{}' is not one of: {}", name,
                               fmt::join(table_estimate_names(), ", ")));
}

std::vector<std::string> observation_symbols(const ModelDescription& description) {
  std::vector<std::string> symbols = description.classes;
  if (description.reject) symbols.emplace_back(kUnknownSymbol);
  return symbols;
}

ObservationModel::ObservationModel(ModelDescription description,
                                   std::vector<ActionModel> per_action)
    : description_(std::move(description)), per_action_(std::move(per_action)) {
  if (per_action_.size() != description_.actions.size())
    throw std::invalid_argument(fmt::format("ObservationModel: {} actions but {} action models",
                                            description_.actions.size(), per_action_.size()));
  for (std::size_t i = 0; i < per_action_.size(); ++i)
    if (!per_action_[i].classifier || per_action_[i].calibration.action != description_.actions[i])
      throw std::invalid_argument("ObservationModel: action model " + std::to_string(i) +
                                  " has no classifier or is not for action '" +
                                  description_.actions[i] + "'");
}

std::vector<std::string> ObservationModel::observation_symbols() const {
  return perception::observation_symbols(description_);
}

const ActionModel& ObservationModel::of(const std::string& action) const {
  const auto& actions = description_.actions;
  const auto it = std::find(actions.begin(), actions.end(), action);
  if (it == actions.end())
    throw InputError(fmt::format("action '{}' is not in the model (it was trained for: {})", action,
                                 fmt::join(actions, ", ")));
  return per_action_[static_cast<std::size_t>(it - actions.begin())];
}

const ActionCalibration& ObservationModel::calibration(const std::string& action) const {
  return of(action).calibration;
}

const Classifier& ObservationModel::classifier(const std::string& action) const {
  return *of(action).classifier;
}

const std::vector<std::vector<double>>& ObservationModel::observation_table(
    const std::string& action) const {
  return calibration(action).table;
}

Prediction ObservationModel::classify(const ClipAnalysis& analysed,
                                      const std::string& action) const {
  const ActionModel& a = of(action);
  const ClassScores scores = a.classifier->score_clip(analysed);
  Prediction p;
  p.action = action;
  p.probabilities = softmax(scores.log_scores, a.calibration.temperature);
  p.best_class = scores.best_class();
  p.distance = scores.nearest_distance();
  p.reject_threshold = a.calibration.reject_threshold;
  p.unknown = description_.reject && p.distance > a.calibration.reject_threshold;
  p.symbol = p.unknown ? static_cast<int>(classes().size()) : p.best_class;
  p.label = p.unknown ? kUnknownSymbol : classes()[static_cast<std::size_t>(p.best_class)];
  return p;
}

}  // namespace echoplan::perception
