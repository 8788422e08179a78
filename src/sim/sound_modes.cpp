#include "sim/sound_modes.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace echoplan::sim {

void render_modes(const std::vector<Mode>& modes, const std::vector<ModeDrive>& drives,
                  const std::vector<float>& friction,
                  std::pair<std::size_t, std::size_t> friction_span,
                  const std::vector<std::size_t>& friction_active, int rate,
                  std::vector<float>& out) {
  constexpr std::size_t kLanes = 4;
  constexpr std::size_t kBlock = 256;
  constexpr double kRestLevel =
      1e-10;  // a resonator this quiet is at rest (~100 dB below the noise floor)
  const std::size_t n_total = std::min(out.size(), friction.size());
  for (std::size_t g = 0; g < modes.size(); g += kLanes) {
    double a1[kLanes] = {}, a2[kLanes] = {}, b[kLanes] = {}, drive[kLanes] = {};
    double y1[kLanes] = {}, y2[kLanes] = {};
    std::size_t first = n_total, end = 0;
    struct Event {
      std::size_t at, lane;
      double amp;
    };
    std::vector<Event> events;
    for (std::size_t lane = 0; lane < kLanes && g + lane < modes.size(); ++lane) {
      const Mode& mode = modes[g + lane];
      const ModeDrive& d = drives[g + lane];
      std::size_t f = n_total, last = 0;
      for (const auto& [at, amp] : d.impulses) {
        if (at >= n_total) continue;
        f = std::min(f, at);
        last = std::max(last, at);
        events.push_back({at, lane, amp});
      }
      if (d.continuous_gain != 0 && friction_span.first <= friction_span.second) {
        f = std::min(f, friction_span.first);
        last = std::max(last, friction_span.second);
        drive[lane] = d.continuous_gain;
      }
      if (f >= n_total) continue;
      const double w = 2.0 * std::numbers::pi * mode.frequency_hz / rate;
      const double r = std::exp(-mode.decay_per_s / rate);
      a1[lane] = 2.0 * r * std::cos(w);
      a2[lane] = -r * r;
      b[lane] = std::sin(w);
      const double tail = mode.decay_per_s > 0 ? kTailDecay / mode.decay_per_s * rate
                                               : static_cast<double>(n_total);
      first = std::min(first, f);
      end = std::max(end,
                     std::min(n_total, last + static_cast<std::size_t>(std::min(tail, 1e9)) + 1));
    }
    if (first >= end) continue;
    std::sort(events.begin(), events.end(),
              [](const Event& x, const Event& y) { return x.at < y.at; });
    std::size_t next_event = 0;
    for (std::size_t block = first; block < end; block += kBlock) {
      const std::size_t block_end = std::min(end, block + kBlock);
      // A silent stretch (every resonator at rest, no friction, no impulse) is skipped: a strike's
      // modes have died away long before its next scuff.
      bool at_rest = friction_active[block_end] == friction_active[block] &&
                     (next_event >= events.size() || events[next_event].at >= block_end);
      for (std::size_t lane = 0; lane < kLanes && at_rest; ++lane)
        at_rest = std::abs(y1[lane]) < kRestLevel && std::abs(y2[lane]) < kRestLevel;
      if (at_rest) {
        for (std::size_t lane = 0; lane < kLanes; ++lane) y1[lane] = y2[lane] = 0;
        continue;
      }
      for (std::size_t n = block; n < block_end; ++n) {
        double x[kLanes];
        for (std::size_t lane = 0; lane < kLanes; ++lane) x[lane] = drive[lane] * friction[n];
        for (; next_event < events.size() && events[next_event].at == n; ++next_event)
          x[events[next_event].lane] += events[next_event].amp;
        double sum = 0;
        for (std::size_t lane = 0; lane < kLanes; ++lane) {
          const double y = a1[lane] * y1[lane] + a2[lane] * y2[lane] + b[lane] * x[lane];
          y2[lane] = y1[lane];
          y1[lane] = y;
          sum += y;
        }
        out[n] += static_cast<float>(sum);
      }
    }
  }
}

double plate_radiation(double frequency_hz, double coincidence_hz) {
  return std::sqrt(std::min(1.0, frequency_hz / coincidence_hz));
}

void render_mode_banks(
    const std::vector<std::pair<const std::vector<Mode>*, const std::vector<ModeDrive>*>>& banks,
    const std::vector<float>& friction, int rate, std::vector<float>& out) {
  std::pair<std::size_t, std::size_t> friction_span{out.size(), 0};
  for (std::size_t n = 0; n < friction.size(); ++n)
    if (friction[n] != 0.0f) {
      friction_span.first = std::min(friction_span.first, n);
      friction_span.second = n;
    }
  // friction_active[n]: how many of the first n samples have friction (to find silent stretches).
  std::vector<std::size_t> friction_active(friction.size() + 1, 0);
  for (std::size_t n = 0; n < friction.size(); ++n)
    friction_active[n + 1] = friction_active[n] + (friction[n] != 0.0f);
  for (const auto& [modes, drives] : banks)
    render_modes(*modes, *drives, friction, friction_span, friction_active, rate, out);
}

}  // namespace echoplan::sim
