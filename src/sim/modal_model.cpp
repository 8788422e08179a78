#include "sim/modal_model.h"

#include <array>
#include <cmath>
#include <numbers>
#include <utility>

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

double shell_mode_frequency(const Material& m, double radius, double thickness, int n,
                            double k_axial) {
  const double nu2 = m.poisson_ratio * m.poisson_ratio;
  const double l2 = (k_axial * radius) * (k_axial * radius);
  const double n2 = static_cast<double>(n) * n;
  const double k = thickness * thickness / (12.0 * radius * radius);
  const double membrane = (1.0 - nu2) * l2 * l2 / ((l2 + n2) * (l2 + n2));
  const double bending = k * (n2 * (n2 - 1.0) * (n2 - 1.0) / (n2 + 1.0) + l2 * l2 + 2.0 * l2 * n2);
  const double omega_scale = std::sqrt(m.youngs_modulus / (m.density * (1.0 - nu2))) / radius;
  return std::sqrt(membrane + bending) * omega_scale / (2.0 * std::numbers::pi);
}

double clamped_plate_frequency(const Material& m, double radius, double thickness,
                               double lambda_squared) {
  // sqrt(D / (rho h)) = h sqrt(E / (12 rho (1 - nu^2))) = h c_b.
  return lambda_squared / (2.0 * std::numbers::pi * radius * radius) * thickness * bending_speed(m);
}

std::vector<Mode> object_modes(const ObjectSpec& o, double max_frequency_hz,
                               double contact_loss_factor, double pad_damping) {
  std::vector<Mode> modes;
  double loss = contact_loss_factor;
  for (const auto& a : o.added_masses) loss += a.loss_factor;
  auto keep = [&](double f, double decay, double gain, int order) {
    if (f < max_frequency_hz)
      modes.push_back({f, decay + std::numbers::pi * f * loss, gain, order});
  };
  if (!o.listed_modes.empty()) {
    for (const auto& l : o.listed_modes) keep(l.frequency, decay_of(l, o.material), l.gain, 0);
    return modes;
  }
  // Mass loading: a mode's frequency falls as sqrt(m / (m + added)) for mass added where it moves.
  const double wall_mass = o.shell_mass * o.wall_thickness * 2.0 * o.height /
                           (o.wall_thickness * 2.0 * o.height + o.radius * o.base_thickness);
  const double base_mass = o.shell_mass - wall_mass;
  double on_base = 0, on_wall = 0;
  for (const auto& a : o.added_masses)
    (a.position[2] <= 0.25 * o.height ? on_base : on_wall) += a.mass;
  const double wall_factor = std::sqrt(wall_mass / (wall_mass + on_wall));
  const double base_factor = std::sqrt(base_mass / (base_mass + on_base));
  // The wall's shell modes, clamped by the base at the bottom and free at the rim. Struck through
  // its base, the wall rings less than the base; higher orders carry less of the energy.
  constexpr double kClampedFreeBeta = 1.8751;
  constexpr double kWallCoupling = 0.6;
  const double r_mid = o.radius - o.wall_thickness / 2.0;
  const double held = pad_damping / (2.0 * (wall_mass + on_wall) / 4.0);
  for (int n = 2; n <= o.ring_modes; ++n) {
    const double f = wall_factor * shell_mode_frequency(o.material, r_mid, o.wall_thickness, n,
                                                        kClampedFreeBeta / o.height);
    keep(f, o.material.decay_rate(f) + held, kWallCoupling / (n - 1), n);
  }
  // The base: a clamped disc's first three modes, struck near its edge.
  constexpr std::array<std::pair<double, double>, 3> kBaseModes{
      {{10.2158, 1.0}, {21.260, 0.4}, {39.771, 0.3}}};
  for (const auto& [lambda2, gain] : kBaseModes) {
    const double base_radius = o.base_radius > 0 ? o.base_radius : o.radius;
    const double f =
        base_factor * clamped_plate_frequency(o.material, base_radius, o.base_thickness, lambda2);
    keep(f, o.material.decay_rate(f), gain, lambda2 == 21.260 ? 1 : 0);
  }
  // A closed tube's air column (both ends closed): its first longitudinal resonance c / 2L, which
  // dominates the sound of an empty can. It loses energy through the walls, so it decays with them.
  if (o.closed) {
    const double f_cavity = kSpeedOfSound / (2.0 * o.height);
    keep(f_cavity, o.material.decay_rate(f_cavity), 1.0, 0);
  }
  return modes;
}

std::vector<Mode> table_modes(const TableSpec& table) {
  std::vector<Mode> modes;
  for (const auto& l : table.modes)
    modes.push_back({l.frequency, decay_of(l, table.material), l.gain, 0});
  // The dense field: even in log frequency, each shifted by a fixed irrational share of its spacing
  // (golden ratio), so the modes are not harmonics of one another.
  const auto& d = table.dense;
  if (d.count > 0) {
    const double step = std::log(d.to_hz / d.from_hz) / d.count;
    for (int i = 0; i < d.count; ++i) {
      const double jitter = std::fmod(0.6180339887 * (i + 1), 1.0);
      const double f = d.from_hz * std::exp(step * (i + jitter));
      modes.push_back({f, table.material.decay_rate(f), 1.0, 0});
    }
  }
  return modes;
}

double coincidence_frequency(const Material& m, double thickness) {
  return kSpeedOfSound * kSpeedOfSound / (2.0 * std::numbers::pi * thickness * bending_speed(m));
}

double plate_point_impedance(const Material& m, double thickness) {
  const double bending_stiffness = m.youngs_modulus * thickness * thickness * thickness /
                                   (12.0 * (1.0 - m.poisson_ratio * m.poisson_ratio));
  return 8.0 * std::sqrt(bending_stiffness * m.density * thickness);
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
