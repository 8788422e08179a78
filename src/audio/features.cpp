// The feature extractor: window, FFT plan, filterbank and DCT prepared once, every feature per
// call. Presets and validation: feature_config.cpp; feature names: feature_names.cpp.
#include "audio/features.h"

#include <fmt/format.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <numbers>

#include "common/error.h"

namespace echoplan::audio {

FeatureExtractor::FeatureExtractor(const FeatureConfig& config)
    : config_((validate_config(config), config)),
      stft_(config.stft),
      filterbank_(config.mel, config.sample_rate, config.stft.fft_size) {
  const auto n_mels = static_cast<std::size_t>(config.mel.n_mels);
  const auto n_mfcc = static_cast<std::size_t>(config.n_mfcc);
  const auto bins = static_cast<std::size_t>(stft_.bins());
  // Orthonormal DCT-II (scipy.fft.dct(type=2, norm="ortho")), first n_mfcc rows.
  dct_.resize(n_mfcc * n_mels);
  for (std::size_t i = 0; i < n_mfcc; ++i) {
    const double scale = std::sqrt((i == 0 ? 1.0 : 2.0) / static_cast<double>(n_mels));
    for (std::size_t m = 0; m < n_mels; ++m)
      dct_[i * n_mels + m] = scale * std::cos(std::numbers::pi * static_cast<double>(i) *
                                              (2.0 * static_cast<double>(m) + 1.0) /
                                              (2.0 * static_cast<double>(n_mels)));
  }
  lifter_.assign(n_mfcc, 1.0);
  if (config.lifter > 0)
    for (std::size_t i = 0; i < n_mfcc; ++i)
      lifter_[i] = 1.0 + config.lifter / 2.0 *
                             std::sin(std::numbers::pi * static_cast<double>(i) / config.lifter);
  bin_hz_.resize(bins);
  for (std::size_t k = 0; k < bins; ++k)
    bin_hz_[k] = static_cast<double>(k) * config.sample_rate / config.stft.fft_size;
  magnitude_.resize(bins);
  previous_magnitude_.resize(bins);
  mel_energy_.resize(n_mels);
  frame_.resize(static_cast<std::size_t>(
      std::max(config.stft.framing.frame_length, config.zcr_framing.frame_length)));
}

void FeatureExtractor::preemphasise(std::span<const float> signal) {
  emphasised_.resize(signal.size());
  if (signal.empty()) return;
  emphasised_[0] = signal[0];
  const double a = config_.preemphasis;
  for (std::size_t n = 1; n < signal.size(); ++n)
    emphasised_[n] =
        static_cast<float>(static_cast<double>(signal[n]) - a * static_cast<double>(signal[n - 1]));
}

void FeatureExtractor::power_spectrogram(std::span<const float> signal, FeatureMatrix& out) {
  if (signal.empty()) throw InputError("cannot compute features of an empty signal");
  std::span<const float> source = signal;
  if (config_.preemphasis != 0.0) {
    preemphasise(signal);
    source = emphasised_;
  }
  stft_.power(source, out);
  if (out.rows == 0)
    throw InputError(fmt::format("signal of {} samples is shorter than one frame ({} samples)",
                                 signal.size(), config_.stft.framing.frame_length));
}

void FeatureExtractor::compute(std::span<const float> signal, Features& out) {
  power_spectrogram(signal, power_);
  spectral_shape(out);
  cepstra(out);
  time_domain(signal, out);
}

// Centroid, bandwidth, roll-off, flatness and flux from the magnitude spectrum |X| = sqrt(power),
// as librosa defines them (bandwidth p = 2; flatness over max(|X|^2, amin)). Each quantity is its
// own simple loop so that the compiler vectorises it.
void FeatureExtractor::spectral_shape(Features& out) {
  const std::size_t frames = power_.rows;
  const std::size_t bins = power_.cols;
  for (FeatureMatrix* m : {&out.centroid, &out.bandwidth, &out.rolloff, &out.flatness, &out.flux})
    m->resize(frames, 1);
  const float amin = static_cast<float>(config_.amin);
  const double* hz = bin_hz_.data();
  for (std::size_t t = 0; t < frames; ++t) {
    const float* power = power_.row(t).data();
    float* mag = magnitude_.data();
    const float* prev = previous_magnitude_.data();
    for (std::size_t k = 0; k < bins; ++k) mag[k] = std::sqrt(power[k]);
    double total = 0.0;
    double weighted = 0.0;
    for (std::size_t k = 0; k < bins; ++k) {
      total += mag[k];
      weighted += mag[k] * hz[k];
    }
    const double centroid = total > 0.0 ? weighted / total : 0.0;
    double spread = 0.0;
    for (std::size_t k = 0; k < bins; ++k)
      spread += mag[k] * (hz[k] - centroid) * (hz[k] - centroid);
    double flux = 0.0;
    for (std::size_t k = 0; k < bins; ++k) flux += std::max(0.0f, mag[k] - prev[k]);
    // Roll-off: the first bin whose cumulative magnitude reaches the fraction of the total.
    const double threshold = config_.rolloff_fraction * total;
    std::size_t rolloff_bin = 0;
    double cumulative = 0.0;
    for (; rolloff_bin + 1 < bins; ++rolloff_bin) {
      cumulative += mag[rolloff_bin];
      if (cumulative >= threshold) break;
    }
    // Flatness needs mean(log p): the product of 16 clamped powers in double stays within range
    // ((1e-18)^16 and, with fft_size <= 2^24, (2^48)^16 are normal doubles), so one log per 16 bins
    // replaces one per bin.
    double log_sum = 0.0;
    double power_sum = 0.0;
    std::size_t k = 0;
    for (; k + 16 <= bins; k += 16) {
      double product = 1.0;
      for (std::size_t j = 0; j < 16; ++j) {
        const double p = std::max(power[k + j], amin);
        power_sum += p;
        product *= p;
      }
      log_sum += std::log(product);
    }
    for (; k < bins; ++k) {
      const double p = std::max(power[k], amin);
      power_sum += p;
      log_sum += std::log(p);
    }
    out.centroid.at(t, 0) = static_cast<float>(centroid);
    out.bandwidth.at(t, 0) = static_cast<float>(total > 0.0 ? std::sqrt(spread / total) : 0.0);
    out.rolloff.at(t, 0) = static_cast<float>(bin_hz_[rolloff_bin]);
    out.flatness.at(t, 0) = static_cast<float>(std::exp(log_sum / static_cast<double>(bins)) /
                                               (power_sum / static_cast<double>(bins)));
    out.flux.at(t, 0) = static_cast<float>(t == 0 ? 0.0 : flux);
    std::swap(magnitude_, previous_magnitude_);
  }
}

// Log filterbank energies and their cepstra.
void FeatureExtractor::cepstra(Features& out) {
  const std::size_t frames = power_.rows;
  const std::size_t n_mels = filterbank_.filters();
  const std::size_t n_mfcc = lifter_.size();
  out.log_mel.resize(frames, n_mels);
  out.mfcc.resize(frames, n_mfcc);
  const double power_scale = config_.power_per_fft_size ? 1.0 / config_.stft.fft_size : 1.0;
  const bool decibel = config_.log_scale == LogScale::decibel;
  double db_max = -HUGE_VAL;
  for (std::size_t t = 0; t < frames; ++t) {
    filterbank_.apply(power_.row(t), mel_energy_);
    auto row = out.log_mel.row(t);
    for (std::size_t m = 0; m < n_mels; ++m) {
      const double e = mel_energy_[m] * power_scale;
      const double value = decibel ? 10.0 * std::log10(std::max(e, config_.amin))
                                   : std::log(e == 0.0 ? DBL_EPSILON : e);
      row[m] = static_cast<float>(value);
      db_max = std::max(db_max, value);
    }
  }
  // power_to_db's top_db floor is relative to the loudest value of the whole spectrogram.
  if (decibel && config_.top_db > 0.0) {
    const auto floor = static_cast<float>(db_max - config_.top_db);
    for (float& v : out.log_mel.values) v = std::max(v, floor);
  }
  for (std::size_t t = 0; t < frames; ++t) {
    const auto log_mel = out.log_mel.row(t);
    auto row = out.mfcc.row(t);
    for (std::size_t i = 0; i < n_mfcc; ++i) {
      const double* basis = dct_.data() + i * n_mels;
      double sum = 0.0;
      for (std::size_t m = 0; m < n_mels; ++m) sum += basis[m] * log_mel[m];
      row[i] = static_cast<float>(sum * lifter_[i]);
    }
    if (config_.energy_in_c0) {
      double energy = 0.0;
      for (float p : power_.row(t)) energy += p;
      energy *= power_scale;
      row[0] = static_cast<float>(std::log(energy == 0.0 ? DBL_EPSILON : energy));
    }
  }
}

// RMS over the STFT framing and zero-crossing rate over its own framing, on the raw (unemphasised)
// signal.
void FeatureExtractor::time_domain(std::span<const float> signal, Features& out) {
  const auto& framing = config_.stft.framing;
  const std::size_t frames = power_.rows;
  out.rms.resize(frames, 1);
  const std::span<float> frame(frame_.data(), static_cast<std::size_t>(framing.frame_length));
  for (std::size_t t = 0; t < frames; ++t) {
    copy_frame(framing, signal, t, frame);
    double sum = 0.0;
    for (float x : frame) sum += static_cast<double>(x) * x;
    out.rms.at(t, 0) = static_cast<float>(std::sqrt(sum / static_cast<double>(frame.size())));
  }

  // librosa.zero_crossings: values within the threshold are zero, and zero counts as positive.
  // Crossings are integers, so frames wholly inside the signal take exact differences of a running
  // count; frames that reach into the padding are counted directly.
  const auto& zcr_framing = config_.zcr_framing;
  const std::size_t zcr_frames = frame_count(zcr_framing, signal.size());
  out.zcr.resize(zcr_frames, 1);
  const float threshold = static_cast<float>(config_.zcr_threshold);
  auto negative = [threshold](float x) { return x < -threshold; };
  crossings_before_.resize(signal.size());
  std::uint32_t running = 0;
  for (std::size_t n = 0; n < signal.size(); ++n) {
    if (n > 0) running += negative(signal[n]) != negative(signal[n - 1]) ? 1u : 0u;
    crossings_before_[n] = running;  // crossings between consecutive samples up to and including n
  }
  const auto length = static_cast<std::size_t>(zcr_framing.frame_length);
  const std::span<float> zframe(frame_.data(), length);
  for (std::size_t t = 0; t < zcr_frames; ++t) {
    const std::ptrdiff_t start = static_cast<std::ptrdiff_t>(t) * zcr_framing.hop -
                                 (zcr_framing.center ? zcr_framing.frame_length / 2 : 0);
    std::size_t crossings = 0;
    if (start >= 0 && static_cast<std::size_t>(start) + length <= signal.size()) {
      crossings = crossings_before_[static_cast<std::size_t>(start) + length - 1] -
                  crossings_before_[static_cast<std::size_t>(start)];
    } else {
      copy_frame(zcr_framing, signal, t, zframe);
      for (std::size_t n = 1; n < length; ++n)
        crossings += negative(zframe[n]) != negative(zframe[n - 1]) ? 1 : 0;
    }
    out.zcr.at(t, 0) =
        static_cast<float>(static_cast<double>(crossings) / static_cast<double>(length));
  }
}

}  // namespace echoplan::audio
