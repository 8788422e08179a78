#include "sim/sound_impacts.h"

#include <cmath>
#include <complex>
#include <numbers>

namespace echoplan::sim {

double hertz_pulse_envelope(double omega, double duration_s) {
  const double x = omega * duration_s / std::numbers::pi;
  return 1.0 / std::sqrt(1.0 + x * x * x * x);
}

double ring_excitation(const std::vector<RimContact>& contacts, int order, double floor) {
  if (order == 0) return 1.0;
  std::complex<double> sum = 0;
  double total = 0;
  for (const auto& c : contacts) {
    sum += c.normal_force * std::polar(1.0, order * c.azimuth_rad);
    total += c.normal_force;
  }
  const double coherent = total > 0 ? std::abs(sum) / total : 1.0;
  return floor + (1.0 - floor) * coherent;
}

void add_impact_impulses(const Impact& impact, std::size_t at, double tau,
                         const RecordingConfig& rec, const std::vector<Mode>& object_modes,
                         double object_mode_scale, const std::vector<Mode>& table_modes,
                         double table_coincidence_hz, std::vector<ModeDrive>& object_drives,
                         std::vector<ModeDrive>& table_drives) {
  const double momentum = impact.effective_mass * impact.normal_speed;
  auto radiated = [&](double f) {
    return f / kReferenceHz * hertz_pulse_envelope(2.0 * std::numbers::pi * f, tau);
  };
  for (std::size_t k = 0; k < object_modes.size(); ++k) {
    const Mode& m = object_modes[k];
    object_drives[k].impulses.emplace_back(
        at, object_mode_scale * momentum * m.gain * radiated(m.frequency_hz) *
                ring_excitation(impact.contacts, m.azimuthal_order, rec.ring_mode_floor));
  }
  for (std::size_t k = 0; k < table_modes.size(); ++k) {
    const Mode& m = table_modes[k];
    table_drives[k].impulses.emplace_back(
        at, rec.table_impact_gain * momentum * m.gain * radiated(m.frequency_hz) *
                plate_radiation(m.frequency_hz, table_coincidence_hz));
  }
}

void add_contact_ring(double gain, double momentum, double tau, double decay_per_s, std::size_t at,
                      int rate, std::vector<float>& out) {
  const double scale =
      gain * momentum * std::numbers::pi / (tau * 2.0 * std::numbers::pi * kReferenceHz);
  const double omega = std::numbers::pi / tau;
  const auto length = static_cast<std::size_t>(std::ceil(kTailDecay / decay_per_s * rate));
  // cos(omega t) e^(-decay t) as a two-pole recursion (exact for the sampled sinusoid).
  const double r = std::exp(-decay_per_s / rate), w = omega / rate;
  double c1 = std::cos(0.5 * w) * std::exp(-0.5 * decay_per_s / rate), c2 = 0;  // n = 0 value
  const double a1 = 2.0 * r * std::cos(w), a2 = -r * r;
  double y_prev = std::cos(-0.5 * w) * std::exp(0.5 * decay_per_s / rate);  // n = -1
  for (std::size_t n = 0; n < length && at + n < out.size(); ++n) {
    out[at + n] += static_cast<float>(scale * c1);
    c2 = a1 * c1 + a2 * y_prev;
    y_prev = c1;
    c1 = c2;
  }
}

}  // namespace echoplan::sim
