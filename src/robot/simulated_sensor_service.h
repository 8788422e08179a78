// The observation service of a simulated world whose model also reads the arm's sensors: the
// clip goes to the classifier as it is, and each modality the model computes from a series is
// computed, with the modality's own series features (perception::ModalityModel::series), from
// what the simulated arm measured during the action just performed: `effort` from its joint
// torques, `force` from its wrist force (sim/arm_sensors.h, with the sensors' noise:
// SimulatedWorld::last_outcome()). So a model trained on `synth-recordings --signals` or
// `collect --signals` trees hears the simulated world as a robot's observation node hears a real
// arm's streams.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "perception/observation_model.h"
#include "robot/classifier_service.h"
#include "robot/simulated_world.h"
#include "signal/series_features.h"

namespace echoplan::robot {

class SimulatedSensorService final : public ObservationService {
 public:
  // The simulated arm's series modalities, the names a model must give them.
  static constexpr const char* kEffort = "effort";
  static constexpr const char* kForce = "force";

  // InputError when a modality of the model without a clip extractor is not one the simulated arm
  // measures (effort, force) computed from a series.
  SimulatedSensorService(std::shared_ptr<SimulatedWorld> world,
                         std::shared_ptr<const perception::ObservationModel> model);

  // Whether `model` reads anything but clips (then a simulated world needs this service).
  static bool reads_sensors(const perception::ObservationModel& model);

  std::optional<ServiceVocabulary> vocabulary() const override { return service_.vocabulary(); }
  // The clip and, for the action's sensor modalities, the readings of the world's last action.
  HeardObservation observe(const audio::AudioClip& clip, const std::string& action) override;

 private:
  // A modality of an action read from the arm: which reading, and its features (parsed once).
  struct Sensor {
    bool effort = true;  // the joint torques; false: the wrist force
    signal::SeriesFeatures features;
  };

  std::shared_ptr<SimulatedWorld> world_;
  ClassifierService service_;
  std::map<std::string, std::vector<Sensor>> sensors_;  // by action, in the model's order
};

}  // namespace echoplan::robot
