#include "perception/observation_model.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <stdexcept>

#include "common/error.h"
#include "perception/modality_fusion.h"

namespace echoplan::perception {

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
  for (std::size_t i = 0; i < per_action_.size(); ++i) {
    const ActionModel& a = per_action_[i];
    bool complete = !a.modalities.empty() && a.weights.size() == a.modalities.size() &&
                    a.calibration.action == description_.actions[i];
    for (const ModalityModel& m : a.modalities) complete = complete && m.classifier != nullptr;
    if (!complete)
      throw std::invalid_argument("ObservationModel: action model " + std::to_string(i) +
                                  " lacks a classifier or a weight, or is not for action '" +
                                  description_.actions[i] + "'");
    if (description_.reject && a.modalities.size() != 1)
      throw std::invalid_argument("ObservationModel: the reject option needs one modality");
  }
}

std::vector<std::string> ObservationModel::observation_symbols() const {
  return perception::observation_symbols(description_);
}

bool ObservationModel::graded() const {
  return std::all_of(per_action_.begin(), per_action_.end(),
                     [](const ActionModel& a) { return a.calibration.grades.has_value(); });
}

bool ObservationModel::levelled() const {
  return std::all_of(per_action_.begin(), per_action_.end(),
                     [](const ActionModel& a) { return a.calibration.level_grades.has_value(); });
}

namespace {

void require_grades(const ObservationModel& model, ObservationKind kind) {
  if (kind == ObservationKind::graded && !model.graded())
    throw InputError(
        "the observation model has no graded observations (it was trained before they existed): "
        "train it again, or plan with `observations: labels`");
  if (kind == ObservationKind::levels && !model.levelled())
    throw InputError(
        "the observation model has no observations graded by level: it was trained on features "
        "without the recordings' measured levels (or before levels existed); train it on a "
        "recordings tree, or plan with `observations: labels`");
}

}  // namespace

std::vector<std::string> ObservationModel::observation_symbols(ObservationKind kind) const {
  if (kind == ObservationKind::labels) return observation_symbols();
  require_grades(*this, kind);
  return graded_symbols(classes(), reject(), kind);
}

int ObservationModel::symbol(const Prediction& heard, ObservationKind kind) const {
  if (kind == ObservationKind::labels) return heard.symbol;
  require_grades(*this, kind);
  const int grade = kind == ObservationKind::levels ? heard.level_grade : heard.grade;
  if (grade < 0)
    throw InputError(fmt::format(
        "the performance of '{}' has no measured level to grade it by (it was not recorded as "
        "audio)",
        heard.action));
  return graded_symbol(heard.symbol, grade, static_cast<int>(classes().size()));
}

const std::vector<std::vector<double>>& ObservationModel::observation_table(
    const std::string& action, ObservationKind kind) const {
  if (kind == ObservationKind::labels) return observation_table(action);
  require_grades(*this, kind);
  return kind == ObservationKind::levels ? calibration(action).level_table
                                         : calibration(action).graded_table;
}

std::vector<std::vector<double>> ObservationModel::untempered_table(const std::string& action,
                                                                    ObservationKind kind) const {
  const std::vector<std::vector<double>>& tempered = observation_table(action, kind);
  const std::optional<ActionFit>& fit = calibration(action).fit;
  if (!fit) return tempered;
  const double beta = kind == ObservationKind::labels   ? fit->temper
                      : kind == ObservationKind::graded ? fit->graded_temper
                                                        : fit->level_temper;
  // (p^beta renormalised)^(1 / beta) renormalised is p.
  return beta == 1.0 ? tempered : temper(tempered, 1.0 / beta);
}

int ObservationModel::action_index(const std::string& action) const {
  const auto& actions = description_.actions;
  const auto it = std::find(actions.begin(), actions.end(), action);
  return it == actions.end() ? -1 : static_cast<int>(it - actions.begin());
}

const ActionModel& ObservationModel::of(const std::string& action) const {
  const int index = action_index(action);
  if (index < 0)
    throw InputError(fmt::format("action '{}' is not in the model (it was trained for: {})", action,
                                 fmt::join(description_.actions, ", ")));
  return per_action_[static_cast<std::size_t>(index)];
}

const ActionCalibration& ObservationModel::calibration(const std::string& action) const {
  return of(action).calibration;
}

const std::vector<ModalityModel>& ObservationModel::modalities(const std::string& action) const {
  return of(action).modalities;
}

const Classifier& ObservationModel::classifier(const std::string& action) const {
  return *of(action).modalities.front().classifier;
}

const std::vector<double>& ObservationModel::weights(const std::string& action) const {
  return of(action).weights;
}

const std::vector<std::vector<double>>& ObservationModel::observation_table(
    const std::string& action) const {
  return calibration(action).table;
}

Prediction ObservationModel::predict(int action, const std::vector<ClassScores>& scores,
                                     std::optional<double> ebr_db) const {
  const ActionModel& a = per_action_[static_cast<std::size_t>(action)];
  std::vector<std::vector<double>> log_scores;
  for (const ClassScores& s : scores) log_scores.push_back(s.log_scores);
  const std::vector<double> fused = fuse(log_scores, a.weights);
  Prediction p;
  p.action = description_.actions[static_cast<std::size_t>(action)];
  p.probabilities = softmax(fused, a.calibration.temperature);
  p.best_class = static_cast<int>(std::max_element(fused.begin(), fused.end()) - fused.begin());
  // The reject option needs one modality (the constructor checks): its distance decides.
  p.distance = scores.front().nearest_distance();
  p.reject_threshold = a.calibration.reject_threshold;
  p.unknown = description_.reject && p.distance > a.calibration.reject_threshold;
  p.symbol = p.unknown ? static_cast<int>(classes().size()) : p.best_class;
  p.label = p.unknown ? kUnknownSymbol : classes()[static_cast<std::size_t>(p.best_class)];
  if (a.calibration.grades)
    p.grade =
        grade_of(*a.calibration.grades, p.probabilities[static_cast<std::size_t>(p.best_class)]);
  if (a.calibration.level_grades && ebr_db)
    p.level_grade = grade_of(*a.calibration.level_grades, *ebr_db);
  return p;
}

Prediction ObservationModel::classify(const ClipAnalysis& analysed,
                                      const std::string& action) const {
  const ActionModel& a = of(action);
  std::vector<ClassScores> scores;
  for (const ModalityModel& m : a.modalities) {
    if (m.classifier->extractor() == nullptr)
      throw InputError(fmt::format(
          "action '{}' needs the '{}' modality's rows, which come from another sensor, not a clip",
          action, m.name));
    scores.push_back(m.classifier->score_clip(analysed));
  }
  return predict(action_index(action), scores, analysed.ebr_db);
}

Prediction ObservationModel::classify_rows(int action,
                                           std::span<const std::span<const double>> rows,
                                           std::optional<double> ebr_db) const {
  const ActionModel& a = per_action_.at(static_cast<std::size_t>(action));
  if (rows.size() != a.modalities.size())
    throw InputError(fmt::format("action '{}' has {} modalities, got {} rows",
                                 description_.actions[static_cast<std::size_t>(action)],
                                 a.modalities.size(), rows.size()));
  std::vector<ClassScores> scores;
  for (std::size_t m = 0; m < rows.size(); ++m)
    scores.push_back(a.modalities[m].classifier->score(rows[m]));
  return predict(action, scores, ebr_db);
}

}  // namespace echoplan::perception
