#include "sim/sound_room.h"

#include <algorithm>
#include <cmath>

namespace echoplan::sim {

std::vector<std::pair<std::size_t, float>> reverb_taps(const RoomConfig& room, int rate, Rng& rng) {
  std::vector<std::pair<std::size_t, float>> taps;
  const int count = static_cast<int>(std::lround(room.taps_per_s * room.length_s));
  const double first_reflection = room.first_reflection_s;
  for (int i = 0; i < count; ++i) {
    const double t = first_reflection + (room.length_s - first_reflection) * uniform01(rng);
    const double sign = uniform01(rng) < 0.5 ? -1.0 : 1.0;
    const double envelope = std::pow(10.0, -3.0 * t / room.rt60_s);
    // Scaled so that the tail's energy, not its tap count, is set by reverb_level.
    const double amplitude =
        sign * room.reverb_level * envelope * std::sqrt(1000.0 / room.taps_per_s);
    taps.emplace_back(static_cast<std::size_t>(std::lround(t * rate)),
                      static_cast<float>(amplitude));
  }
  return taps;
}

void add_delayed(const std::vector<float>& in, std::size_t delay, float gain,
                 std::vector<float>& out) {
  if (delay >= out.size()) return;
  const std::size_t n = std::min(in.size(), out.size() - delay);
  float* o = out.data() + delay;
  const float* x = in.data();
  for (std::size_t i = 0; i < n; ++i) o[i] += gain * x[i];
}

std::vector<float> add_room(const std::vector<float>& dry,
                            const std::vector<std::pair<std::size_t, float>>& taps) {
  constexpr std::size_t kBlock = 4096;
  std::vector<float> room = dry;
  const std::size_t frames = dry.size();
  for (std::size_t start = 0; start < frames; start += kBlock) {
    const std::size_t end = std::min(frames, start + kBlock);
    float* o = room.data();
    for (const auto& [delay, gain] : taps) {
      if (delay >= end) continue;
      const std::size_t from = std::max(start, delay);
      const float* x = dry.data() + (from - delay);
      for (std::size_t i = from; i < end; ++i) o[i] += gain * x[i - from];
    }
  }
  return room;
}

}  // namespace echoplan::sim
