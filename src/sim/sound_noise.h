// Noise for the sound synthesis: one fast, platform-independent source of unit noise per clip,
// and the room's low-frequency background made from it.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numbers>
#include <vector>

#include "common/rng.h"

namespace echoplan::sim {

// Zero-mean, unit-variance noise: Irwin-Hall sum of four 16-bit uniforms from one 64-bit SplitMix64
// output. The generator is seeded once from the recording's Rng: one engine call per clip instead
// of one per sample, and identical on every platform.
class NoiseSource {
 public:
  explicit NoiseSource(Rng& rng) : state_(rng()) {}
  float next() {
    const std::uint64_t z = splitmix64_next(state_);
    const std::uint64_t sum =
        (z & 0xFFFF) + ((z >> 16) & 0xFFFF) + ((z >> 32) & 0xFFFF) + (z >> 48);
    return static_cast<float>((static_cast<double>(sum) / 65536.0 - 2.0) * std::numbers::sqrt3);
  }

 private:
  std::uint64_t state_;
};

// A band-pass biquad (RBJ's cookbook, constant 0 dB peak gain) centred on `hz` with quality `q`,
// at `rate`: the band of the arm's motors.
class BandPass {
 public:
  BandPass(double hz, double q, int rate) {
    const double w0 = 2.0 * std::numbers::pi * hz / rate;
    const double bandwidth = std::sin(w0) / (2.0 * q);
    const double a0 = 1 + bandwidth;
    b0_ = bandwidth / a0;
    b2_ = -bandwidth / a0;
    a1_ = -2 * std::cos(w0) / a0;
    a2_ = (1 - bandwidth) / a0;
  }
  double filter(double x) {
    const double y = b0_ * x + b2_ * x2_ - a1_ * y1_ - a2_ * y2_;
    x2_ = x1_;
    x1_ = x;
    y2_ = y1_;
    y1_ = y;
    return y;
  }

 private:
  double b0_ = 0, b2_ = 0, a1_ = 0, a2_ = 0;
  double x1_ = 0, x2_ = 0, y1_ = 0, y2_ = 0;
};

// The room's noise at `rms`, flat below `corner_hz` and falling 6 dB per octave above it (white
// through a one-pole low-pass). A real room's noise is dominated by low frequencies (ventilation,
// traffic, the building: ANSI/ASA S12.2's room-criterion curves fall 5 dB per octave band from
// 16 Hz), and the lab's templates carried far more 100-500 Hz than white noise does; what it does
// to the realism targets is in docs/simulator.md ("The room's noise"). Both capsules hear it alike:
// it is the room's, and they are 10 cm apart in it.
std::vector<float> room_noise(std::size_t frames, int rate, double corner_hz, double rms,
                              NoiseSource& noise);

}  // namespace echoplan::sim
