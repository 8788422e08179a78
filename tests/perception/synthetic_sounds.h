// Synthetic recordings for the perception tests: struck "objects" as sums of decaying modes, with
// the real robot's quirks on demand (leading digital zeros, a noise floor, a strike at another
// force). Generated at test time from a seed, so the repository ships no audio and every clip is
// reproducible.
#pragma once

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "audio/clip.h"
#include "audio/io.h"

namespace echoplan::perception::test_sounds {

// One object's sound: modes (Hz, decay time s, amplitude).
struct Mode {
  double hz;
  double decay_s;
  double amplitude;
};

struct StrikeOptions {
  int sample_rate = 44100;
  double duration_s = 1.5;
  double leading_zeros_s =
      0.0;                 // exact digital zeros before anything (the real recorder's opening)
  double onset_s = 0.3;    // when the strike happens, from the start of the clip
  double gain = 0.5;       // peak-ish amplitude of the strike (force)
  double noise_rms = 0.0;  // stationary noise from the end of the zeros onwards (robot noise)
  double detune = 0.0;     // relative random spread of mode frequencies between recordings
  unsigned seed = 1;
};

inline audio::AudioClip strike(const std::vector<Mode>& modes, const StrikeOptions& o) {
  std::mt19937 rng(o.seed);
  std::normal_distribution<double> gauss(0.0, 1.0);
  audio::AudioClip clip;
  clip.sample_rate = o.sample_rate;
  clip.channels = 1;
  const auto n = static_cast<std::size_t>(o.duration_s * o.sample_rate);
  clip.samples.assign(n, 0.0f);
  std::vector<double> hz;
  for (const auto& m : modes) hz.push_back(m.hz * (1.0 + o.detune * gauss(rng)));
  const auto zeros = static_cast<std::size_t>(o.leading_zeros_s * o.sample_rate);
  const auto onset = static_cast<std::size_t>(o.onset_s * o.sample_rate);
  for (std::size_t i = zeros; i < n; ++i) {
    double x = o.noise_rms * gauss(rng);
    if (i >= onset) {
      const double t = static_cast<double>(i - onset) / o.sample_rate;
      for (std::size_t k = 0; k < modes.size(); ++k)
        x += o.gain * modes[k].amplitude * std::exp(-t / modes[k].decay_s) *
             std::sin(2.0 * std::numbers::pi * hz[k] * t);
    }
    clip.samples[i] = static_cast<float>(std::clamp(x, -1.0, 1.0));
  }
  return clip;
}

// Three objects that a few-shot classifier should tell apart: a low dull thud, a ringing mid mode,
// a bright click.
inline const std::vector<std::vector<Mode>>& three_objects() {
  static const std::vector<std::vector<Mode>> objects{
      {{420.0, 0.05, 0.6}, {1130.0, 0.03, 0.3}},
      {{880.0, 0.25, 0.5}, {2350.0, 0.12, 0.2}},
      {{2900.0, 0.02, 0.5}, {5100.0, 0.015, 0.4}},
  };
  return objects;
}

// A fresh empty folder under the test temp dir.
inline std::filesystem::path fresh_dir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("echoplan_perception_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace echoplan::perception::test_sounds
