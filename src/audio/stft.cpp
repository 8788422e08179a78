#include "audio/stft.h"

#include <fmt/format.h>
#include <kiss_fftr.h>

#include <algorithm>

#include "common/error.h"

namespace echoplan::audio {

// The KISS FFT plan and its complex output buffer, hidden so that callers never see kissfft's
// headers.
struct Stft::Plan {
  kiss_fftr_cfg cfg = nullptr;
  std::vector<kiss_fft_cpx> spectrum;
  ~Plan() { kiss_fftr_free(cfg); }
};

Stft::Stft(const StftConfig& config) : config_(config) {
  validate_framing(config.framing);
  // kiss_fftr needs an even size; 2^24 bounds memory (and is far beyond any audio frame).
  if (config.fft_size < 2 || config.fft_size % 2 != 0 || config.fft_size > (1 << 24))
    throw InputError(fmt::format("fft_size {} must be even, between 2 and 2^24", config.fft_size));
  if (config.fft_size < config.framing.frame_length)
    throw InputError(fmt::format("fft_size {} is smaller than frame_length {}", config.fft_size,
                                 config.framing.frame_length));
  window_ = make_window(config.window, config.framing.frame_length);
  plan_ = std::make_unique<Plan>();
  plan_->cfg = kiss_fftr_alloc(config.fft_size, 0, nullptr, nullptr);
  if (plan_->cfg == nullptr) throw std::bad_alloc();
  plan_->spectrum.resize(static_cast<std::size_t>(bins()));
  frame_.resize(static_cast<std::size_t>(config.framing.frame_length));
  buffer_.assign(static_cast<std::size_t>(config.fft_size), 0.0f);
}

Stft::~Stft() = default;
Stft::Stft(Stft&&) noexcept = default;
Stft& Stft::operator=(Stft&&) noexcept = default;

void Stft::frame_power(std::span<const float> frame, std::span<float> out) {
  // Window into the start of the FFT buffer; the tail beyond frame_length stays zero from
  // construction.
  for (std::size_t n = 0; n < window_.size(); ++n) buffer_[n] = frame[n] * window_[n];
  kiss_fftr(plan_->cfg, buffer_.data(), plan_->spectrum.data());
  for (std::size_t k = 0; k < plan_->spectrum.size(); ++k) {
    const kiss_fft_cpx c = plan_->spectrum[k];
    out[k] = c.r * c.r + c.i * c.i;
  }
}

void Stft::power(std::span<const float> signal, FeatureMatrix& out) {
  const std::size_t frames = frame_count(config_.framing, signal.size());
  if (out.rows != frames || out.cols != static_cast<std::size_t>(bins()))
    out.resize(frames, static_cast<std::size_t>(bins()));
  for (std::size_t t = 0; t < frames; ++t) {
    copy_frame(config_.framing, signal, t, frame_);
    frame_power(frame_, out.row(t));
  }
}

}  // namespace echoplan::audio
