#include "sim/modal_model.h"

#include <cmath>
#include <numbers>

namespace echoplan::sim {

namespace {

// sqrt(E / (12 rho (1 - nu^2))): the bending wave speed factor of a plate or shell wall (m/s).
double bending_speed(const Material& m) {
  return std::sqrt(m.youngs_modulus /
                   (12.0 * m.density * (1.0 - m.poisson_ratio * m.poisson_ratio)));
}

double decay_of(const ListedMode& listed, const Material& material) {
  return listed.decay > 0 ? listed.decay : material.decay_rate(listed.frequency);
}

}  // namespace

std::vector<Mode> object_modes(const ObjectSpec& o, double max_frequency_hz) {
  std::vector<Mode> modes;
  auto keep = [&](Mode mode) {
    if (mode.frequency_hz < max_frequency_hz) modes.push_back(mode);
  };
  if (!o.listed_modes.empty()) {
    for (const auto& l : o.listed_modes) keep({l.frequency, decay_of(l, o.material), l.gain, 0});
    return modes;
  }
  const double two_pi = 2.0 * std::numbers::pi;
  const double c_b = bending_speed(o.material);
  // Shell ring modes: higher orders are stiffer and, struck at a point, carry less of the energy.
  for (int n = 2; n <= o.ring_modes; ++n) {
    const double shape = n * (n * n - 1.0) / std::sqrt(n * n + 1.0);
    const double f = o.wall_thickness / (two_pi * o.radius * o.radius) * c_b * shape;
    keep({f, o.material.decay_rate(f), 1.0 / (n - 1), n});
  }
  // The base: a clamped disc's first mode, f = 10.21 / (2 pi R^2) * h * c_b.
  const double f_base = 10.21 / (two_pi * o.radius * o.radius) * o.base_thickness * c_b;
  keep({f_base, o.material.decay_rate(f_base), 0.5, 0});
  // A closed tube's air column (both ends closed): its first longitudinal resonance c / 2L, which
  // dominates the sound of an empty can. It loses energy through the walls, so it decays with them.
  if (o.closed) {
    const double f_cavity = kSpeedOfSound / (2.0 * o.height);
    keep({f_cavity, o.material.decay_rate(f_cavity), 1.5, 0});
  }
  return modes;
}

std::vector<Mode> table_modes(const TableSpec& table) {
  std::vector<Mode> modes;
  for (const auto& l : table.modes)
    modes.push_back({l.frequency, decay_of(l, table.material), l.gain, 0});
  return modes;
}

double effective_modulus(const Material& a, const Material& b) {
  return 1.0 / ((1.0 - a.poisson_ratio * a.poisson_ratio) / a.youngs_modulus +
                (1.0 - b.poisson_ratio * b.poisson_ratio) / b.youngs_modulus);
}

double hertz_contact_time(double mass_kg, double radius_m, double e_star_pa, double speed_m_s) {
  return 2.87 * std::pow(mass_kg * mass_kg / (radius_m * e_star_pa * e_star_pa * speed_m_s), 0.2);
}

double half_sine_pulse_spectrum(double omega, double duration_s) {
  // F(t) = (pi / 2 tau) sin(pi t / tau) on [0, tau] has unit impulse and
  // |F(w)| = |cos(w tau / 2)| / |1 - (w tau / pi)^2|; at w tau = pi the ratio is 0/0 -> pi/4.
  const double x = omega * duration_s / std::numbers::pi;
  const double denominator = 1.0 - x * x;
  if (std::abs(denominator) < 1e-9) return std::numbers::pi / 4.0;
  return std::abs(std::cos(omega * duration_s / 2.0) / denominator);
}

}  // namespace echoplan::sim
