// A small synthetic recording set (three struck objects, actions "strike" and "tap", four
// recordings each) and the model trained on it with default options: built once per test binary,
// shared by the observation model's tests. Tests may write files into its folder (model files,
// held-out sets); the folder is removed at exit.
#pragma once

#include <fmt/format.h>

#include <filesystem>
#include <fstream>
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

// Three objects struck on two tables; on "soft" every mode sounds 40% lower and dies three times as
// fast (what a table the model never heard might do). Recording i of each (object, table) is
// session i.
inline std::filesystem::path write_two_tables(const std::string& name) {
  const std::filesystem::path dir = test_sounds::fresh_dir(name);
  std::ofstream manifest(dir / "manifest.csv");
  manifest << "file,object,action,session,surface\n";
  for (std::size_t k = 0; k < kObjects.size(); ++k)
    for (const std::string table : {"hard", "soft"})
      for (unsigned i = 0; i < 3; ++i) {
        std::vector<test_sounds::Mode> modes = test_sounds::three_objects()[k];
        if (table == "soft")
          for (auto& m : modes) m = {m.hz * 0.6, m.decay_s * 0.3, m.amplitude};
        const unsigned seed = 100 * static_cast<unsigned>(k) + 10 * (table == "soft") + i;
        const std::string file = fmt::format("{}/strike/{}{}.wav", kObjects[k], table, i);
        std::filesystem::create_directories((dir / file).parent_path());
        audio::write_audio((dir / file).string(), test_sounds::strike(modes, {.onset_s = 0.4,
                                                                              .gain = 0.3 + 0.1 * i,
                                                                              .noise_rms = 0.0005,
                                                                              .detune = 0.02,
                                                                              .seed = seed}));
        manifest << fmt::format("{},{},strike,{},{}\n", file, kObjects[k], i + 1, table);
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
