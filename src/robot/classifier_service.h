// The observation service of a trained observation model (src/perception): a clip and its action
// in, the model's class (or `unknown`) with calibrated probabilities out.
//
// The model is shared read-only (its classify() is thread-safe); the service owns the clip analyser
// and its buffers, so each worker thread of a campaign builds its own service over the same model.
#pragma once

#include <memory>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "perception/clip_analysis.h"
#include "perception/observation_model.h"
#include "robot/observation_service.h"

namespace echoplan::robot {

class ClassifierService final : public ObservationService {
 public:
  explicit ClassifierService(std::shared_ptr<const perception::ObservationModel> model);

  // Per action of the model, its classes; `unknown` when the model's reject option is on.
  std::optional<ServiceVocabulary> vocabulary() const override;
  // Analyses the clip once (any rate and channel count), classifies it with `action`'s classifier
  // and fills `features` with clip_summary(). Throws InputError listing the model's actions for an
  // action it was not trained for, and for a clip too short to analyse.
  HeardObservation observe(const audio::AudioClip& clip, const std::string& action) override;

  // The modalities of `action` whose rows another sensor gives (no clip extractor: a feature set's
  // haptic.csv, a robot's feature topic), in the model's order; empty for an action heard from
  // its clip alone and for an action the model does not know.
  std::vector<std::string> sensor_modalities(const std::string& action) const;
  // Classifies one performance of `action` from its sensors' rows (one per sensor_modalities(), in
  // that order) and, when the action also has modalities computed from clips, its clip (analysed
  // as observe() does; `features` then summarises it). InputError for an unknown action, a row
  // count that does not match, a row of the wrong length, and a clip needed but not given (null).
  HeardObservation observe_performance(const std::string& action,
                                       std::span<const std::vector<double>> sensor_rows,
                                       const audio::AudioClip* clip);

  const perception::ObservationModel& model() const { return *model_; }

 private:
  HeardObservation heard(const perception::Prediction& p) const;

  std::shared_ptr<const perception::ObservationModel> model_;
  perception::ClipAnalyzer analyzer_;
  perception::ClipAnalysis analysis_;  // reused from clip to clip
};

// What a log says about a clip, from its analysis at `sample_rate` Hz: onset_s (the sound event's
// start), duration_s, peak_dbfs (loudest frame's RMS, dB re full scale), and, over the 1.5 s after
// the onset, centroid_hz (mean spectral centroid of frames louder than 40 dB below the peak) and
// flatness (their mean spectral flatness, 0 tonal .. 1 noise).
std::vector<std::pair<std::string, double>> clip_summary(const perception::ClipAnalysis& analysis,
                                                         int sample_rate);

}  // namespace echoplan::robot
