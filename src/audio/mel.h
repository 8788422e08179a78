// Mel filterbanks: triangular filters on the mel scale, applied to a power spectrum.
//
// Two constructions, one per reference library:
//  - psf_bins (python_speech_features): HTK mel scale 2595 log10(1 + f/700) (the same as 1125 ln(1
//  + f/700));
//    filter edges snapped to FFT bins floor((N + 1) f / sr); peak weight 1; no normalisation;
//  - slaney (librosa default): Slaney's mel scale (linear below 1 kHz, logarithmic above);
//  continuous
//    triangles over the bin frequencies k sr / N; each filter scaled by 2 / (upper edge - lower
//    edge) Hz.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

namespace echoplan::audio {

enum class MelFilterStyle { psf_bins, slaney };

// Mel <-> Hz on the HTK scale (2595 log10(1 + f/700)) and on Slaney's scale.
double hz_to_mel_htk(double hz);
double mel_to_hz_htk(double mel);
double hz_to_mel_slaney(double hz);
double mel_to_hz_slaney(double mel);

// Plain description of a filterbank. Invariants (checked by MelFilterbank): n_mels >= 1,
// 0 <= fmin < fmax <= sample_rate / 2, fft_size >= 2.
struct MelConfig {
  MelFilterStyle style = MelFilterStyle::slaney;
  int n_mels = 128;
  double fmin_hz = 0.0;
  double fmax_hz = 0.0;  // 0 means sample_rate / 2
};

// A filterbank precomputed for one (sample rate, FFT size); stored sparsely (each filter's non-zero
// run) so applying it costs one multiply-add per non-zero weight.
class MelFilterbank {
 public:
  MelFilterbank(const MelConfig& config, int sample_rate, int fft_size);

  std::size_t filters() const { return first_bin_.size(); }
  std::size_t bins() const { return bins_; }

  // out[m] = sum_k weight[m][k] * power[k], accumulated in double. power has bins() values, out
  // filters().
  void apply(std::span<const float> power, std::span<double> out) const;

  // Dense weight of filter m at bin k (0 outside its support); for tests and plots.
  double weight(std::size_t m, std::size_t k) const;

 private:
  std::size_t bins_ = 0;
  std::vector<std::size_t> first_bin_;        // per filter: first bin with a non-zero weight
  std::vector<std::vector<double>> weights_;  // per filter: weights from first_bin_ on
};

}  // namespace echoplan::audio
