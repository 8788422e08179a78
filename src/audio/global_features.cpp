// Whole-signal features (declared in audio/features.h): the report's "global" RMS, zero crossings
// and magnitude-weighted spectral centroid of the whole clip's DFT.
#include <fmt/format.h>
#include <kiss_fft.h>

#include <cmath>
#include <memory>

#include "audio/features.h"
#include "common/error.h"

namespace echoplan::audio {
namespace {

std::size_t largest_prime_factor(std::size_t n) {
  std::size_t largest = 1;
  for (std::size_t p = 2; p * p <= n; ++p)
    while (n % p == 0) {
      largest = p;
      n /= p;
    }
  return n > 1 ? n : largest;
}

// Smallest length >= n whose only prime factors are 2, 3 and 5 (fast for KISS FFT).
std::size_t next_smooth_length(std::size_t n) {
  for (std::size_t m = n;; ++m) {
    std::size_t r = m;
    for (std::size_t p : {2u, 3u, 5u})
      while (r % p == 0) r /= p;
    if (r == 1) return m;
  }
}

struct KissFree {
  void operator()(kiss_fft_state* cfg) const { kiss_fft_free(cfg); }
};

}  // namespace

GlobalFeatures global_features(std::span<const float> signal, int sample_rate) {
  if (signal.empty()) throw InputError("cannot compute features of an empty signal");
  if (sample_rate < 1)
    throw InputError(fmt::format("sample rate {} Hz must be positive", sample_rate));
  GlobalFeatures out;
  double energy = 0.0;
  for (float x : signal) energy += static_cast<double>(x) * x;
  out.rms = std::sqrt(energy / static_cast<double>(signal.size()));
  for (std::size_t n = 1; n < signal.size(); ++n)
    out.zero_crossings += (signal[n] < 0.0f) != (signal[n - 1] < 0.0f) ? 1 : 0;

  // KISS FFT's generic radix costs N * p for a prime factor p: keep the exact length while that
  // stays below 2^27 operations (~0.1 s), otherwise pad to a 2-3-5-smooth length (bounded time for
  // any input).
  constexpr double kMaxExactCost = 134217728.0;
  std::size_t length = signal.size();
  if (static_cast<double>(length) * static_cast<double>(largest_prime_factor(length)) >
      kMaxExactCost)
    length = next_smooth_length(length);
  std::unique_ptr<kiss_fft_state, KissFree> cfg(
      kiss_fft_alloc(static_cast<int>(length), 0, nullptr, nullptr));
  if (!cfg) throw std::bad_alloc();
  std::vector<kiss_fft_cpx> in(length, kiss_fft_cpx{0.0f, 0.0f});
  std::vector<kiss_fft_cpx> spectrum(length);
  for (std::size_t n = 0; n < signal.size(); ++n) in[n].r = signal[n];
  kiss_fft(cfg.get(), in.data(), spectrum.data());
  // numpy.fft.rfft bins 0 .. N/2 at frequency k * sr / N.
  double total = 0.0;
  double weighted = 0.0;
  for (std::size_t k = 0; k <= length / 2; ++k) {
    const double mag =
        std::hypot(static_cast<double>(spectrum[k].r), static_cast<double>(spectrum[k].i));
    total += mag;
    weighted += mag * static_cast<double>(k) * sample_rate / static_cast<double>(length);
  }
  out.centroid_hz = total > 0.0 ? weighted / total : 0.0;
  return out;
}

}  // namespace echoplan::audio
