#include "audio/mel.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "common/error.h"

namespace echoplan::audio {
namespace {

// numpy.linspace(start, stop, num): start + i * step, with the last point set to stop exactly.
// Matching numpy to the last bit matters for psf, whose filter edges are floor()ed.
std::vector<double> linspace(double start, double stop, int num) {
  std::vector<double> out(static_cast<std::size_t>(num));
  const double step = num > 1 ? (stop - start) / (num - 1) : 0.0;
  for (int i = 0; i < num; ++i) out[static_cast<std::size_t>(i)] = start + i * step;
  if (num > 1) out.back() = stop;
  return out;
}

// Slaney's scale: linear (3 mels per 200 Hz) below 1 kHz, then logarithmic with 27 mels per
// factor 6.4.
constexpr double kSlaneyHzPerMel = 200.0 / 3.0;
constexpr double kSlaneyBreakHz = 1000.0;
constexpr double kSlaneyBreakMel = kSlaneyBreakHz / kSlaneyHzPerMel;
const double kSlaneyLogStep = std::log(6.4) / 27.0;

}  // namespace

double hz_to_mel_htk(double hz) { return 2595.0 * std::log10(1.0 + hz / 700.0); }
double mel_to_hz_htk(double mel) { return 700.0 * (std::pow(10.0, mel / 2595.0) - 1.0); }

double hz_to_mel_slaney(double hz) {
  if (hz < kSlaneyBreakHz) return hz / kSlaneyHzPerMel;
  return kSlaneyBreakMel + std::log(hz / kSlaneyBreakHz) / kSlaneyLogStep;
}

double mel_to_hz_slaney(double mel) {
  if (mel < kSlaneyBreakMel) return kSlaneyHzPerMel * mel;
  return kSlaneyBreakHz * std::exp(kSlaneyLogStep * (mel - kSlaneyBreakMel));
}

MelFilterbank::MelFilterbank(const MelConfig& config, int sample_rate, int fft_size) {
  const double nyquist = sample_rate / 2.0;
  const double fmax = config.fmax_hz > 0.0 ? config.fmax_hz : nyquist;
  if (config.n_mels < 1 || config.n_mels > 1024)
    throw InputError(fmt::format("n_mels {} must be in 1..1024", config.n_mels));
  if (!(config.fmin_hz >= 0.0 && config.fmin_hz < fmax && fmax <= nyquist))
    throw InputError(
        fmt::format("mel range {}..{} Hz must satisfy 0 <= fmin < fmax <= sample_rate/2 = {} Hz",
                    config.fmin_hz, fmax, nyquist));
  if (fft_size < 2) throw InputError(fmt::format("fft_size {} must be at least 2", fft_size));
  bins_ = static_cast<std::size_t>(fft_size / 2 + 1);
  const auto n_mels = static_cast<std::size_t>(config.n_mels);
  std::vector<std::vector<double>> dense(n_mels, std::vector<double>(bins_, 0.0));

  if (config.style == MelFilterStyle::psf_bins) {
    // python_speech_features.get_filterbanks: edges at floor((nfft + 1) * hz / sr), ramps between
    // them.
    const auto mels =
        linspace(hz_to_mel_htk(config.fmin_hz), hz_to_mel_htk(fmax), config.n_mels + 2);
    std::vector<double> edge(mels.size());
    for (std::size_t i = 0; i < mels.size(); ++i)
      edge[i] = std::floor((fft_size + 1) * mel_to_hz_htk(mels[i]) / sample_rate);
    for (std::size_t m = 0; m < n_mels; ++m) {
      for (auto k = static_cast<std::size_t>(edge[m]);
           k < static_cast<std::size_t>(edge[m + 1]) && k < bins_; ++k)
        dense[m][k] = (static_cast<double>(k) - edge[m]) / (edge[m + 1] - edge[m]);
      for (auto k = static_cast<std::size_t>(edge[m + 1]);
           k < static_cast<std::size_t>(edge[m + 2]) && k < bins_; ++k)
        dense[m][k] = (edge[m + 2] - static_cast<double>(k)) / (edge[m + 2] - edge[m + 1]);
    }
  } else {
    // librosa.filters.mel(htk=False, norm="slaney"): triangles in Hz between consecutive mel
    // points, evaluated at each bin's frequency, then area-normalised by 2 / (f[m+2] - f[m]).
    const auto mels =
        linspace(hz_to_mel_slaney(config.fmin_hz), hz_to_mel_slaney(fmax), config.n_mels + 2);
    std::vector<double> hz(mels.size());
    for (std::size_t i = 0; i < mels.size(); ++i) hz[i] = mel_to_hz_slaney(mels[i]);
    for (std::size_t m = 0; m < n_mels; ++m) {
      const double enorm = 2.0 / (hz[m + 2] - hz[m]);
      for (std::size_t k = 0; k < bins_; ++k) {
        const double f = static_cast<double>(k) * sample_rate / fft_size;  // numpy.fft.rfftfreq
        const double lower = (f - hz[m]) / (hz[m + 1] - hz[m]);
        const double upper = (hz[m + 2] - f) / (hz[m + 2] - hz[m + 1]);
        dense[m][k] = std::max(0.0, std::min(lower, upper)) * enorm;
      }
    }
  }

  // Keep each filter's run from its first to its last non-zero weight.
  first_bin_.resize(n_mels);
  weights_.resize(n_mels);
  for (std::size_t m = 0; m < n_mels; ++m) {
    const auto& row = dense[m];
    const auto first = std::find_if(row.begin(), row.end(), [](double w) { return w != 0.0; });
    const auto last =
        std::find_if(row.rbegin(), row.rend(), [](double w) { return w != 0.0; }).base();
    first_bin_[m] = static_cast<std::size_t>(first - row.begin());
    if (first < last) weights_[m].assign(first, last);
  }
}

void MelFilterbank::apply(std::span<const float> power, std::span<double> out) const {
  for (std::size_t m = 0; m < first_bin_.size(); ++m) {
    const float* p = power.data() + first_bin_[m];
    const auto& w = weights_[m];
    double sum = 0.0;
    for (std::size_t j = 0; j < w.size(); ++j) sum += w[j] * p[j];
    out[m] = sum;
  }
}

double MelFilterbank::weight(std::size_t m, std::size_t k) const {
  if (k < first_bin_[m] || k >= first_bin_[m] + weights_[m].size()) return 0.0;
  return weights_[m][k - first_bin_[m]];
}

}  // namespace echoplan::audio
