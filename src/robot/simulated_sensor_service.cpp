#include "robot/simulated_sensor_service.h"

#include <fmt/format.h>

#include <stdexcept>

#include "common/error.h"
#include "signal/series_features.h"

namespace echoplan::robot {

namespace {

// The modality `m` of `action` as the simulated arm can give it: an InputError saying why not.
void check_modality(const perception::ModalityModel& m, const std::string& action) {
  if (m.classifier->extractor() != nullptr) return;  // computed from the clip
  const bool measured =
      m.name == SimulatedSensorService::kEffort || m.name == SimulatedSensorService::kForce;
  if (!measured || m.series.empty())
    throw InputError(fmt::format(
        "the model reads '{}' of '{}' {}; the simulated arm measures series of {} (joint torques) "
        "and {} (wrist force): train on a recordings tree of those (synth-recordings --signals)",
        m.name, action, m.series.empty() ? "as rows given by a sensor" : "from a series",
        SimulatedSensorService::kEffort, SimulatedSensorService::kForce));
}

}  // namespace

SimulatedSensorService::SimulatedSensorService(
    std::shared_ptr<SimulatedWorld> world,
    std::shared_ptr<const perception::ObservationModel> model)
    : world_(std::move(world)), service_(std::move(model)) {
  for (const std::string& action : service_.model().actions())
    for (const perception::ModalityModel& m : service_.model().modalities(action)) {
      check_modality(m, action);
      if (m.classifier->extractor() == nullptr)
        sensors_[action].push_back({m.name == kEffort, signal::parse_series_features(m.series)});
    }
}

bool SimulatedSensorService::reads_sensors(const perception::ObservationModel& model) {
  for (const std::string& action : model.actions())
    for (const perception::ModalityModel& m : model.modalities(action))
      if (m.classifier->extractor() == nullptr) return true;
  return false;
}

HeardObservation SimulatedSensorService::observe(const audio::AudioClip& clip,
                                                 const std::string& action) {
  const auto& outcome = world_->last_outcome();
  if (!outcome)
    throw std::logic_error("SimulatedSensorService::observe before the world's first action");
  std::vector<std::vector<double>> rows;
  if (const auto it = sensors_.find(action); it != sensors_.end())
    for (const Sensor& s : it->second)
      rows.push_back(s.features.extract(
          s.effort ? outcome->readings.effort : outcome->readings.force,
          s.effort ? "the simulated arm's effort" : "the simulated arm's force"));
  return service_.observe_performance(action, rows, &clip);
}

}  // namespace echoplan::robot
