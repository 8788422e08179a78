// Onset detection on a spectral-flux envelope, and fixed-size feature windows aligned on an onset.
//
// The observation model compares recordings frame by frame; aligning each clip on its sound event
// (the first or strongest onset) instead of trimming at fixed times makes those frames comparable.
#pragma once

#include <cstddef>
#include <vector>

#include "audio/matrix.h"

namespace echoplan::audio {

// Peak picking in the style of librosa.util.peak_pick, on the flux envelope scaled to a maximum
// of 1. Frame t is an onset when flux[t] is the maximum of flux[t - pre_max .. t + post_max], at
// least mean(flux[t - pre_avg .. t + post_avg]) + delta, and at least `wait` frames after the
// previous onset.
struct OnsetConfig {
  int pre_max = 3;      // frames
  int post_max = 3;     // frames
  int pre_avg = 10;     // frames
  int post_avg = 10;    // frames
  double delta = 0.07;  // in units of the envelope's maximum
  int wait = 10;        // frames
};

// Onset frame indices (ascending) of a flux envelope (frames x 1, e.g. Features::flux). An envelope
// that is all zeros (silence) has no onsets. Throws InputError if a config field is negative.
std::vector<std::size_t> detect_onsets(const FeatureMatrix& flux, const OnsetConfig& config = {});

enum class OnsetChoice {
  first,      // the earliest detected onset
  strongest,  // the detected onset with the largest flux
};

// The frame to align on: the chosen detected onset, or, if none is detected, the frame of maximum
// flux (frame 0 for silence). flux must have at least one row.
std::size_t alignment_frame(const FeatureMatrix& flux, OnsetChoice choice,
                            const OnsetConfig& config = {});

// A fixed-size window of `before + after` rows of `features` starting at row anchor - before. Rows
// outside the matrix repeat the nearest edge row, so every clip gives the same shape (the templates
// the observation model averages). features must have at least one row.
FeatureMatrix onset_window(const FeatureMatrix& features, std::size_t anchor, std::size_t before,
                           std::size_t after);

}  // namespace echoplan::audio
