// The analysis every classifier starts from: one clip turned into frame-wise features at the
// model's rate, with the frame its sound event starts on.
//
// Real recordings do not line up in time: the robot's recorder opens with about 0.35 s of digital
// zeros, clips last 2-4 s, and a strike at another force is louder or softer (shared reference:
// real-robot-recordings.md). Classifiers therefore compare frames relative to the sound's onset
// (found on the spectral-flux envelope after the leading digital silence), never at fixed frame
// offsets, and compare levels only where they mean to.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "audio/clip.h"
#include "audio/features.h"
#include "audio/onsets.h"

namespace echoplan::perception {

// How clips are analysed; stored in the model file so that classification repeats training exactly.
struct AnalysisSettings {
  int sample_rate = 44100;  // Hz; every clip is mixed to mono and resampled to this rate
  std::string preset =
      "psf";  // audio::preset_by_name: python_speech_features framing (25 ms / 10 ms)
  audio::OnsetConfig onset;  // peak picking on the flux envelope
  // Frames whose RMS is at or below this (full-scale units) count as digital silence when it leads
  // the clip; the onset search starts after it. 0 keeps only exact zeros out.
  double silence_rms = 1e-6;
};

// One analysed clip. Frame-wise matrices follow audio::Features (one row per 10 ms frame with psf).
struct ClipAnalysis {
  int sample_rate = 0;                // Hz of `mono` (AnalysisSettings::sample_rate)
  std::vector<float> mono;            // samples at AnalysisSettings::sample_rate
  audio::Features features;           // every frame-wise feature of `mono`
  std::size_t first_sound_frame = 0;  // first frame after the leading digital silence
  std::size_t onset_frame = 0;        // the strongest onset at or after first_sound_frame
  double hop_seconds = 0.01;          // seconds between frames
  // The clip's event-to-background ratio as measured from it (audio/levels.h), in dB: how noisy it
  // is, what an observation of kind `levels` is graded by.
  double ebr_db = 0.0;
};

// Turns clips into ClipAnalysis. Holds a configured audio::FeatureExtractor and its buffers, so one
// analyser must not be used from two threads at once; create one per thread.
class ClipAnalyzer {
 public:
  // Validates the settings (InputError naming the bad parameter).
  explicit ClipAnalyzer(const AnalysisSettings& settings);

  const AnalysisSettings& settings() const { return settings_; }

  // Analyses `clip` (any rate and channel count: mixed to mono and resampled first). `name` is used
  // in error messages (a file path). Throws InputError for an empty clip or one shorter than a
  // frame.
  void analyse(const audio::AudioClip& clip, const std::string& name, ClipAnalysis& out);

  // Same, for a mono signal already at settings().sample_rate.
  void analyse_mono(std::vector<float> mono, const std::string& name, ClipAnalysis& out);

 private:
  AnalysisSettings settings_;
  audio::FeatureExtractor extractor_;
};

// The first frame after a clip's leading digital silence: the first frame whose RMS exceeds
// `silence_rms` (0 if the first frame already does; rms.rows - 1 for a clip that is silent
// throughout).
std::size_t first_sound_frame(const audio::FeatureMatrix& rms, double silence_rms);

// The frame a clip's sound event starts on: the strongest onset of the flux envelope at or after
// `from` (audio::alignment_frame over flux rows from .. end). Louder and softer copies of the same
// sound give the same frame, since the envelope is scaled to its maximum before peak picking.
std::size_t onset_frame(const audio::FeatureMatrix& flux, std::size_t from,
                        const audio::OnsetConfig& onset);

}  // namespace echoplan::perception
