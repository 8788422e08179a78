// Per-channel energy normalisation (PCEN; Wang et al. 2017, "Trainable frontend for robust and
// far-field keyword spotting"; the parameters as librosa.pcen defaults them, Lostanlen et al.
// 2019): each band's energy divided by a slow running average of its own recent energy, then
// compressed,
//
//   M[t] = (1 - s) M[t-1] + s E[t]
//   P[t] = (E[t] / (eps + M[t])^gain + bias)^power - bias^power
//
// so a stationary background of any level maps to about the same small value and a sound event
// stands out by how far it rises above the background that preceded it: a front end the field uses
// where a classifier must hear events through noise.
#pragma once

#include <cstddef>
#include <vector>

#include "audio/matrix.h"

namespace echoplan::audio {

struct PcenConfig {
  double time_constant_s = 0.4;  // of the running average M
  double gain = 0.98;            // alpha: how fully E is divided by M (1 = fully)
  double bias = 2.0;             // delta
  double power = 0.5;            // r: root compression
  double eps = 1e-6;             // keeps the division finite where M is 0
};

// The smoother's coefficient s for a time constant and a frame hop, librosa's: with T the time
// constant in frames, s = (sqrt(1 + 4 T^2) - 1) / (2 T^2). InputError unless both are positive.
double pcen_smoothing(double time_constant_s, double hop_s);

// Where the running average starts: at frame `frame`, equal to `average` (one energy per band), or
// when that is empty to the frame's own energy (a steady state, as librosa starts it). Rows before
// `frame` are 0: a recorder's leading digital silence is no background to divide by.
struct PcenStart {
  std::size_t frame = 0;
  std::vector<double> average;
};

// PCEN of `energies` (frames x bands, linear energies, not logs) whose frames are `hop_s` apart.
// InputError for a parameter out of range (gain and power in (0, 1], bias and eps positive), a
// start past the last frame of a non-empty matrix, or a start average with another band count.
FeatureMatrix pcen(const FeatureMatrix& energies, double hop_s, const PcenConfig& config,
                   const PcenStart& start = {});

}  // namespace echoplan::audio
