// A small synthetic recording set (three struck objects, actions "strike" and "tap", four
// recordings each) and the model trained on it with default options: built once per test binary,
// shared by the observation model's tests. Tests may write files into its folder (model files,
// held-out sets); the folder is removed at exit.
#pragma once

#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "perception/observation_model.h"
#include "synthetic_sounds.h"

namespace echoplan::perception::test_model {

inline const std::vector<std::string> kObjects{"thud", "ring", "click"};

// A strike of object k with the real recorder's quirks: leading zeros, noise, random force and
// detuning.
inline audio::AudioClip recording(std::size_t k, unsigned seed, double gain_lo = 0.2,
                                  double gain_hi = 0.8) {
  std::mt19937 rng(seed);
  const double gain = std::uniform_real_distribution<double>(gain_lo, gain_hi)(rng);
  const double onset = std::uniform_real_distribution<double>(0.5, 0.8)(rng);
  return test_sounds::strike(test_sounds::three_objects()[k], {.duration_s = 1.8,
                                                               .leading_zeros_s = 0.35,
                                                               .onset_s = onset,
                                                               .gain = gain,
                                                               .noise_rms = 0.0005,
                                                               .detune = 0.02,
                                                               .seed = seed});
}

// "tap" is the same strike 12 dB softer.
inline std::filesystem::path write_training_set(const std::string& name) {
  const std::filesystem::path dir = test_sounds::fresh_dir(name);
  for (std::size_t k = 0; k < kObjects.size(); ++k)
    for (const std::string action : {"strike", "tap"})
      for (unsigned i = 0; i < 4; ++i) {
        auto clip = recording(k, 10 * static_cast<unsigned>(k) + i + (action == "tap" ? 500 : 0));
        if (action == "tap")
          for (float& x : clip.samples) x *= 0.25f;
        const std::filesystem::path path =
            dir / kObjects[k] / action / (std::to_string(i) + ".wav");
        std::filesystem::create_directories(path.parent_path());
        audio::write_audio(path.string(), clip);
      }
  return dir;
}

struct TrainedModel {
  std::filesystem::path dir = write_training_set("model");
  // Loaded before any test writes into the folder (which then is no recording set).
  RecordingSet set = load_recording_set(dir.string());
  ObservationModel model = train_observation_model(set, FitOptions{});
  ~TrainedModel() { std::filesystem::remove_all(dir); }
};

inline const TrainedModel& trained() {
  static const TrainedModel t;
  return t;
}

// `clip` analysed the way the model analyses (what the classify command and the robot's
// classifier service do before ObservationModel::classify).
inline ClipAnalysis analysed(const ObservationModel& model, const audio::AudioClip& clip) {
  ClipAnalyzer analyzer(model.analysis());
  ClipAnalysis out;
  analyzer.analyse(clip, "clip", out);
  return out;
}

}  // namespace echoplan::perception::test_model
