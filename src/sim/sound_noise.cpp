#include "sim/sound_noise.h"

#include <cmath>

namespace echoplan::sim {

std::vector<float> room_noise(std::size_t frames, int rate, double corner_hz, double rms,
                              NoiseSource& noise) {
  std::vector<float> out(frames);
  const double a = 1.0 - std::exp(-2.0 * std::numbers::pi * corner_hz / rate);
  // A one-pole low-pass y += a (x - y) passes a / (2 - a) of unit white noise's power.
  const double gain = rms * std::sqrt((2.0 - a) / a);
  // Started in its steady state (a draw of the filtered process) rather than at zero, so the first
  // samples are as loud as the rest.
  double y = std::sqrt(a / (2.0 - a)) * noise.next();
  for (float& x : out) {
    y += a * (noise.next() - y);
    x = static_cast<float>(gain * y);
  }
  return out;
}

}  // namespace echoplan::sim
