// Feature configuration: the two reference presets and the parameter table validation reads.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "audio/features.h"
#include "common/error.h"

namespace echoplan::audio {
namespace {

// python_speech_features rounds frame length and step half up (decimal ROUND_HALF_UP).
int round_half_up(double x) { return static_cast<int>(std::floor(x + 0.5)); }

int next_power_of_two(int n) {
  int p = 1;
  while (p < n) p *= 2;
  return p;
}

}  // namespace

FeatureConfig psf_preset(int sample_rate) {
  FeatureConfig c;
  c.sample_rate = sample_rate;
  c.stft.framing = {.frame_length = round_half_up(0.025 * sample_rate),
                    .hop = round_half_up(0.01 * sample_rate),
                    .center = false,
                    .center_pad = PadMode::zeros,
                    .pad_tail = true};
  c.stft.fft_size = std::max(2, next_power_of_two(c.stft.framing.frame_length));
  c.stft.window = WindowKind::rectangular;
  c.preemphasis = 0.97;
  c.power_per_fft_size = true;
  c.mel = {.style = MelFilterStyle::psf_bins, .n_mels = 26, .fmin_hz = 0.0, .fmax_hz = 0.0};
  c.log_scale = LogScale::natural_log;
  c.n_mfcc = 13;
  c.lifter = 22;
  c.energy_in_c0 = true;
  c.zcr_framing = c.stft.framing;
  return c;
}

FeatureConfig librosa_preset(int sample_rate) {
  FeatureConfig c;
  c.sample_rate = sample_rate;
  c.stft.framing = {.frame_length = 2048,
                    .hop = 512,
                    .center = true,
                    .center_pad = PadMode::zeros,
                    .pad_tail = false};
  c.stft.fft_size = 2048;
  c.stft.window = WindowKind::hann_periodic;
  c.mel = {.style = MelFilterStyle::slaney, .n_mels = 128, .fmin_hz = 0.0, .fmax_hz = 0.0};
  c.log_scale = LogScale::decibel;
  c.amin = 1e-10;
  c.top_db = 80.0;
  c.n_mfcc = 20;
  c.lifter = 0;
  c.energy_in_c0 = false;
  c.zcr_framing = c.stft.framing;
  c.zcr_framing.center_pad = PadMode::edge;
  return c;
}

FeatureConfig preset_by_name(std::string_view name, int sample_rate) {
  if (name == "psf") return psf_preset(sample_rate);
  if (name == "librosa") return librosa_preset(sample_rate);
  throw InputError(fmt::format("unknown feature preset '{}' (expected psf or librosa)", name));
}

std::vector<ParameterInfo> describe_parameters(const FeatureConfig& c) {
  const double nyquist = c.sample_rate / 2.0;
  const double big = 1 << 24;
  return {
      {"sample_rate", "Hz", 1, 1e6, double(c.sample_rate),
       "rate of the signal the extractor will see"},
      {"frame_length", "samples", 1, big, double(c.stft.framing.frame_length),
       "samples per STFT frame"},
      {"hop", "samples", 1, big, double(c.stft.framing.hop), "samples between STFT frames"},
      {"fft_size", "samples", std::max(2.0, double(c.stft.framing.frame_length)), big,
       double(c.stft.fft_size), "FFT length (even, >= frame_length)"},
      {"preemphasis", "", 0, 1, c.preemphasis,
       "pre-emphasis coefficient a in y[n] = x[n] - a x[n-1]"},
      {"n_mels", "", 1, 1024, double(c.mel.n_mels), "mel filters"},
      {"fmin", "Hz", 0, nyquist, c.mel.fmin_hz, "lowest mel filter edge"},
      {"fmax", "Hz", 0, nyquist, c.mel.fmax_hz, "highest mel filter edge (0 = sample_rate / 2)"},
      // Flatness multiplies 16 clamped powers before one log: amin^16 must stay a normal double.
      {"amin", "power", 1e-18, 1, c.amin, "decibel and flatness floor of power"},
      {"top_db", "dB", 0, 1000, c.top_db, "dynamic range kept below the maximum (0 = unlimited)"},
      {"n_mfcc", "", 1, double(c.mel.n_mels), double(c.n_mfcc),
       "cepstral coefficients (at most n_mels)"},
      {"lifter", "", 0, 1000, double(c.lifter), "sinusoidal lifter length L (0 = off)"},
      {"rolloff_fraction", "", 0, 1, c.rolloff_fraction,
       "fraction of spectral magnitude below the roll-off"},
      {"zcr_frame_length", "samples", 1, big, double(c.zcr_framing.frame_length),
       "samples per zero-crossing frame"},
      {"zcr_hop", "samples", 1, big, double(c.zcr_framing.hop),
       "samples between zero-crossing frames"},
      {"zcr_threshold", "", 0, 1, c.zcr_threshold, "|x| at or below this counts as zero"},
  };
}

void validate_config(const FeatureConfig& config) {
  for (const auto& p : describe_parameters(config)) {
    if (!(p.value >= p.min && p.value <= p.max))  // written so that NaN fails too
      throw InputError(fmt::format("parameter {} = {} {} is outside {}..{}: {}", p.name, p.value,
                                   p.unit, p.min, p.max, p.description));
  }
  if (config.stft.fft_size % 2 != 0)
    throw InputError(
        fmt::format("parameter fft_size = {} samples must be even", config.stft.fft_size));
  const double fmax = config.mel.fmax_hz > 0 ? config.mel.fmax_hz : config.sample_rate / 2.0;
  if (config.mel.fmin_hz >= fmax)
    throw InputError(
        fmt::format("parameter fmin = {} Hz must be below fmax = {} Hz", config.mel.fmin_hz, fmax));
}

}  // namespace echoplan::audio
