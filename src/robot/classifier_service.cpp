#include "robot/classifier_service.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "common/error.h"

namespace echoplan::robot {

ClassifierService::ClassifierService(std::shared_ptr<const perception::ObservationModel> model)
    : model_(std::move(model)),
      analyzer_((model_ ? *model_ : throw std::invalid_argument("ClassifierService: no model"))
                    .analysis()) {}

std::optional<ServiceVocabulary> ClassifierService::vocabulary() const {
  ServiceVocabulary v;
  for (const std::string& action : model_->actions()) v.labels[action] = model_->classes();
  v.may_report_unknown = model_->reject();
  v.grades = model_->graded();
  v.levels = model_->levelled();
  return v;
}

HeardObservation ClassifierService::observe(const audio::AudioClip& clip,
                                            const std::string& action) {
  model_->calibration(
      action);  // an action the model was not trained for: InputError listing its actions
  analyzer_.analyse(clip, "the recording of " + action, analysis_);
  const perception::Prediction p = model_->classify(analysis_, action);
  HeardObservation h = heard(p);
  h.features = clip_summary(analysis_, analyzer_.settings().sample_rate);
  return h;
}

HeardObservation ClassifierService::heard(const perception::Prediction& p) const {
  HeardObservation h;
  h.label = p.label;
  h.unknown = p.unknown;
  h.probability = p.probabilities.at(static_cast<std::size_t>(p.best_class));
  h.grade = p.grade;
  h.level_grade = p.level_grade;
  const auto& classes = model_->classes();
  for (std::size_t k = 0; k < classes.size(); ++k)
    h.probabilities.emplace_back(classes[k], p.probabilities[k]);
  h.distance = p.distance;
  return h;
}

std::vector<std::string> ClassifierService::sensor_modalities(const std::string& action) const {
  std::vector<std::string> names;
  if (model_->action_index(action) < 0) return names;
  for (const perception::ModalityModel& m : model_->modalities(action))
    if (m.classifier->extractor() == nullptr) names.push_back(m.name);
  return names;
}

HeardObservation ClassifierService::observe_performance(
    const std::string& action, std::span<const std::vector<double>> sensor_rows,
    const audio::AudioClip* clip) {
  const auto& modalities = model_->modalities(action);  // InputError for an unknown action
  const std::vector<std::string> sensors = sensor_modalities(action);
  if (sensor_rows.size() != sensors.size())
    throw InputError(fmt::format("'{}' needs {} sensor row(s) ({}), got {}", action, sensors.size(),
                                 fmt::join(sensors, ", "), sensor_rows.size()));
  // The model's rows in its modality order: a sensor's as given, a clip's computed from it.
  std::vector<std::vector<double>> computed;
  computed.reserve(modalities.size());
  std::vector<std::span<const double>> rows;
  std::size_t next_sensor = 0;
  bool analysed = false;
  for (const perception::ModalityModel& m : modalities) {
    if (m.classifier->extractor() == nullptr) {
      rows.emplace_back(sensor_rows[next_sensor++]);
      continue;
    }
    if (clip == nullptr || clip->samples.empty())
      throw InputError(fmt::format(
          "'{}' needs the clip of the performance for its '{}' modality, and none was recorded",
          action, m.name));
    if (!analysed) analyzer_.analyse(*clip, "the recording of " + action, analysis_);
    analysed = true;
    computed.push_back(m.classifier->embed(analysis_));
    rows.emplace_back(computed.back());
  }
  HeardObservation h = heard(
      model_->classify_rows(model_->action_index(action), rows,
                            analysed ? std::optional<double>(analysis_.ebr_db) : std::nullopt));
  if (analysed) h.features = clip_summary(analysis_, analyzer_.settings().sample_rate);
  return h;
}

std::vector<std::pair<std::string, double>> clip_summary(const perception::ClipAnalysis& a,
                                                         int sample_rate) {
  const audio::Features& f = a.features;
  const std::size_t frames = f.rms.rows;
  const double hop = a.hop_seconds;
  double peak = 0;
  for (std::size_t t = 0; t < frames; ++t)
    peak = std::max(peak, static_cast<double>(f.rms.at(t, 0)));
  // The event's frames: from the onset for 1.5 s (a slide lasts about that long), loud enough to be
  // the event rather than the room.
  constexpr double kEventSeconds = 1.5, kFloorRatio = 0.01;  // 40 dB below the peak
  const std::size_t end =
      std::min(frames, a.onset_frame + static_cast<std::size_t>(kEventSeconds / hop));
  double centroid = 0, flatness = 0;
  int counted = 0;
  for (std::size_t t = a.onset_frame; t < end && t < f.centroid.rows; ++t) {
    if (f.rms.at(t, 0) < kFloorRatio * peak) continue;
    centroid += f.centroid.at(t, 0);
    flatness += f.flatness.at(t, 0);
    ++counted;
  }
  const double n = std::max(counted, 1);
  return {{"onset_s", static_cast<double>(a.onset_frame) * hop},
          {"duration_s", static_cast<double>(a.mono.size()) / sample_rate},
          {"peak_dbfs", peak > 0 ? 20.0 * std::log10(peak) : -200.0},
          {"centroid_hz", centroid / n},
          {"flatness", flatness / n}};
}

}  // namespace echoplan::robot
