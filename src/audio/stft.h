// Short-time Fourier transform: frames a signal, windows each frame and takes its real FFT (KISS
// FFT, planned once at construction and reused for every frame and every call).
//
// Precision: KISS FFT as packaged by Debian computes in float32, so each bin carries an absolute
// error of roughly 1e-7 * sqrt(fft_size) times the frame's RMS amplitude; power in bins far below
// the frame's strongest bins is correspondingly imprecise in relative terms (see docs/audio.md).
#pragma once

#include <cstddef>
#include <memory>
#include <span>
#include <vector>

#include "audio/framing.h"
#include "audio/matrix.h"
#include "audio/window.h"

namespace echoplan::audio {

// Plain configuration of an STFT. Invariants (checked at construction): fft_size even and
// >= framing.frame_length; the window covers the frame and the frame sits at the start of the FFT
// buffer, zero-padded to fft_size (python_speech_features' rfft(frame, NFFT)).
struct StftConfig {
  FramingConfig framing;
  int fft_size = 2048;
  WindowKind window = WindowKind::hann_periodic;
};

// One configured STFT. Not thread-safe (it owns scratch buffers); make one per thread.
class Stft {
 public:
  // Validates `config` (InputError naming the parameter) and plans the FFT.
  explicit Stft(const StftConfig& config);
  ~Stft();
  Stft(Stft&&) noexcept;
  Stft& operator=(Stft&&) noexcept;

  const StftConfig& config() const { return config_; }
  int bins() const { return config_.fft_size / 2 + 1; }  // rfft bins: 0 .. fft_size / 2

  // Squared magnitude |X[t, k]|^2 of every frame: out is frames x bins (frame_count rows). `out` is
  // resized only when its shape changes, so a reused matrix does not allocate.
  void power(std::span<const float> signal, FeatureMatrix& out);

  // Squared magnitude of one arbitrary frame of fft_size samples (already framed; the window is
  // applied here) into `out` (bins values).
  void frame_power(std::span<const float> frame, std::span<float> out);

 private:
  struct Plan;
  StftConfig config_;
  std::vector<float> window_;
  std::unique_ptr<Plan> plan_;
  std::vector<float> frame_;   // frame_length samples, before windowing
  std::vector<float> buffer_;  // fft_size samples, windowed and zero-padded
};

}  // namespace echoplan::audio
