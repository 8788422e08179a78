// Frame-wise and whole-signal audio features, computed by an extractor configured once and run many
// times.
//
// A FeatureConfig (plain struct) names every parameter; two presets reproduce the reference
// libraries:
//  - psf_preset(sr): python_speech_features 0.6.1 mfcc/logfbank (25 ms / 10 ms start-aligned frames
//  with
//    a zero-padded tail, rectangular window, FFT size the next power of two >= the frame,
//    pre-emphasis 0.97, 26 filters, natural log, 13 cepstra, lifter 22, c0 = log frame energy);
//  - librosa_preset(sr): librosa 0.11 defaults (n_fft 2048, hop 512, periodic Hann, centred with
//  zeros,
//    128 Slaney mels, power_to_db(ref 1, amin 1e-10, top_db 80), 20 cepstra, no lifter).
// FeatureExtractor validates a config once (InputError naming the parameter, its unit and its
// range), precomputes the window, FFT plan, filterbank and DCT matrix, and then compute() fills a
// Features with every feature of a mono signal, reusing its buffers (no allocation once shapes are
// stable).
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "audio/matrix.h"
#include "audio/mel.h"
#include "audio/stft.h"

namespace echoplan::audio {

// How filterbank energies become log features.
enum class LogScale {
  natural_log,  // ln(E), E == 0 replaced by DBL_EPSILON (python_speech_features)
  decibel,      // 10 log10(max(E, amin)), then floored at (matrix maximum - top_db) (librosa
                // power_to_db)
};

// Every parameter of feature extraction. Plain data; FeatureExtractor checks it.
struct FeatureConfig {
  int sample_rate = 22050;  // Hz of the signal the extractor will see
  StftConfig stft;
  double preemphasis = 0.0;  // y[n] = x[n] - a x[n-1] over the whole signal before framing; 0 = off
  bool power_per_fft_size =
      false;  // filterbank input |X|^2 / fft_size (psf powspec) instead of |X|^2
  MelConfig mel;
  LogScale log_scale = LogScale::decibel;
  double amin = 1e-10;        // decibel floor of power (librosa amin)
  double top_db = 80.0;       // decibel dynamic range kept below the maximum; 0 = no floor
  int n_mfcc = 20;            // cepstral coefficients kept (DCT-II, orthonormal)
  int lifter = 0;             // sinusoidal liftering 1 + (L/2) sin(pi n / L); 0 = off
  bool energy_in_c0 = false;  // replace c0 by ln(frame power-spectrum energy)
  double rolloff_fraction =
      0.85;  // spectral roll-off: fraction of magnitude below the roll-off bin
  FramingConfig
      zcr_framing;  // framing of the zero-crossing rate (librosa pads it with edge samples)
  double zcr_threshold = 1e-10;  // |x| <= threshold counts as zero (positive) in crossings
};

FeatureConfig psf_preset(int sample_rate);
FeatureConfig librosa_preset(int sample_rate);
// "psf" or "librosa"; anything else throws InputError listing the presets.
FeatureConfig preset_by_name(std::string_view name, int sample_rate);

// One parameter as a user sees it: for --help, docs and configure-time validation.
struct ParameterInfo {
  std::string name;  // e.g. "n_mels"
  std::string unit;  // e.g. "Hz", "samples", "" for counts
  double min = 0;    // inclusive range
  double max = 0;
  double value = 0;  // the config's value
  std::string description;
};

// The numeric parameters of `config` with their ranges. validate_config() checks each against its
// range and the cross-parameter rules (fft_size >= frame_length, fmax <= sample_rate / 2, n_mfcc <=
// n_mels), throwing InputError("parameter <name> = <value> <unit> is outside <min>..<max>:
// <description>").
std::vector<ParameterInfo> describe_parameters(const FeatureConfig& config);
void validate_config(const FeatureConfig& config);

// Every feature of one signal. Frame-wise matrices have one row per STFT frame (except zcr, which
// has one row per frame of zcr_framing). Units: rms and signal in full-scale units; centroid,
// bandwidth and rolloff in Hz; flatness in [0, 1]; flux in magnitude units; log_mel in ln or dB;
// mfcc dimensionless.
struct Features {
  FeatureMatrix log_mel;    // frames x n_mels
  FeatureMatrix mfcc;       // frames x n_mfcc
  FeatureMatrix centroid;   // frames x 1: sum f |X| / sum |X| (0 for a silent frame)
  FeatureMatrix bandwidth;  // frames x 1: sqrt(sum |X| (f - centroid)^2 / sum |X|)
  FeatureMatrix rolloff;    // frames x 1: lowest f with cumulative |X| >= rolloff_fraction * total
  FeatureMatrix flatness;   // frames x 1: geometric / arithmetic mean of max(|X|^2, amin)
  FeatureMatrix flux;       // frames x 1: sum_k max(0, |X_t| - |X_t-1|); 0 for the first frame
  FeatureMatrix rms;        // frames x 1: sqrt(mean x^2) over the unwindowed, unemphasised frame
  FeatureMatrix zcr;  // zcr frames x 1: sign changes between consecutive samples / frame_length
};

// One frame-wise feature of a Features, by kind; names as on the command line.
enum class FeatureKind { log_mel, mfcc, centroid, bandwidth, rolloff, flatness, flux, rms, zcr };

// "logmel", "mfcc", "centroid", "bandwidth", "rolloff", "flatness", "flux", "rms", "zcr".
std::string_view feature_name(FeatureKind kind);
// Throws InputError listing the valid names.
FeatureKind feature_from_name(std::string_view name);
const FeatureMatrix& select_feature(const Features& features, FeatureKind kind);

// Features of the whole signal at once (the report's "global" features).
struct GlobalFeatures {
  double rms = 0.0;              // sqrt(mean x^2)
  long long zero_crossings = 0;  // sign changes between consecutive samples; 0 counts as positive
  double centroid_hz =
      0.0;  // magnitude-weighted mean frequency of the whole signal's DFT (0 if silent)
};

// Whole-signal features. The DFT has the signal's exact length N when N's largest prime factor p
// keeps the mixed-radix FFT cheap (N * p <= 2^27); otherwise the signal is zero-padded to the next
// length whose factors are 2, 3 and 5 (a finer-sampled spectrum of the same signal; documented in
// docs/audio.md). Throws InputError for an empty signal or a non-positive sample rate.
GlobalFeatures global_features(std::span<const float> signal, int sample_rate);

class FeatureExtractor {
 public:
  // Validates (validate_config) and precomputes window, FFT plan, filterbank and DCT matrix.
  explicit FeatureExtractor(const FeatureConfig& config);

  const FeatureConfig& config() const { return config_; }

  // Fills `out` with every feature of the mono `signal` (at config().sample_rate). Throws
  // InputError for an empty signal or one too short for a single frame of a start-aligned framing
  // without tail padding. Pure silence is valid: log features take their floor (ln DBL_EPSILON, or
  // -100 dB with amin 1e-10), spectral shape features are 0 (flatness 1).
  void compute(std::span<const float> signal, Features& out);

  // Only the power spectrogram (frames x bins) of the preset's STFT, including pre-emphasis: the
  // "floor" every spectral feature starts from.
  void power_spectrogram(std::span<const float> signal, FeatureMatrix& out);

 private:
  void preemphasise(std::span<const float> signal);
  void spectral_shape(Features& out);
  void cepstra(Features& out);
  void time_domain(std::span<const float> signal, Features& out);

  FeatureConfig config_;
  Stft stft_;
  MelFilterbank filterbank_;
  std::vector<double> dct_;     // n_mfcc x n_mels, row-major, orthonormal DCT-II
  std::vector<double> lifter_;  // n_mfcc weights
  std::vector<double> bin_hz_;  // frequency of each rfft bin
  // Scratch reused across calls.
  std::vector<float> emphasised_;
  FeatureMatrix power_;
  std::vector<float> magnitude_;  // bins of the current frame
  std::vector<float> previous_magnitude_;
  std::vector<double> mel_energy_;
  std::vector<float> frame_;
  std::vector<std::uint32_t> crossings_before_;  // running zero-crossing count per sample
};

}  // namespace echoplan::audio
