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

// The wall's shell modes are clamped by the base at the bottom and free at the rim: the
// clamped-free beam function's first axial wavenumber is 1.8751 / height.
constexpr double kClampedFreeBeta = 1.8751;
// Struck or rubbed through its base, the wall rings less than the base. A balance set with the
// modes against the lab's strike and slide spectra (../shared/reference/real-robot-recordings.md,
// "Measures per file"); no measurement of its own. It belongs to the object, not the lab, so it is
// not in the sim config (docs/simulator.md, "Tuned constants").
constexpr double kWallCoupling = 0.6;

// How added masses load a mode at `frequency_hz` (its unloaded frequency): mass on the base (within
// a quarter of the height) loads the base's modes, mass higher up the wall's, each with the share
// of it that follows the object at that frequency (AddedMass::share_at).
struct Loading {
  double wall_mass = 0, base_mass = 0, on_wall = 0, on_base = 0;
  double wall_factor = 1;  // sqrt(m / (m + added)): the wall's modes fall so
  double base_factor = 1;  // and the base's
  double modal_mass = 0;   // a quarter of the loaded wall (cos n theta around, clamped-free along)
  double held_decay = 0;   // 1/s: the finger pads' damping on the wall's modal mass, c / (2 m)
};

Loading loading_at(const ObjectSpec& o, double pad_damping, double frequency_hz) {
  Loading w;
  w.wall_mass = o.shell_mass * o.wall_thickness * 2.0 * o.height /
                (o.wall_thickness * 2.0 * o.height + o.radius * o.base_thickness);
  w.base_mass = o.shell_mass - w.wall_mass;
  for (const auto& a : o.added_masses)
    (a.position[2] <= 0.25 * o.height ? w.on_base : w.on_wall) += a.mass * a.share_at(frequency_hz);
  w.wall_factor = std::sqrt(w.wall_mass / (w.wall_mass + w.on_wall));
  w.base_factor = std::sqrt(w.base_mass / (w.base_mass + w.on_base));
  w.modal_mass = (w.wall_mass + w.on_wall) / 4.0;
  w.held_decay = pad_damping / (2.0 * w.modal_mass);
  return w;
}

// m, the wall's mid-surface, where the shell formula takes its radius.
double mid_radius(const ObjectSpec& o) { return o.radius - o.wall_thickness / 2.0; }

// The loss factor every mode gets besides its material's: pressed on the table, and from each
// added mass's fixing.
double added_loss_factor(const ObjectSpec& o, double contact_loss_factor) {
  double loss = contact_loss_factor;
  for (const auto& a : o.added_masses) loss += a.loss_factor;
  return loss;
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
  const double loss = added_loss_factor(o, contact_loss_factor);
  auto keep = [&](double f, double decay, double gain, int order) {
    if (f < max_frequency_hz)
      modes.push_back({f, decay + std::numbers::pi * f * loss, gain, order});
  };
  if (!o.listed_modes.empty()) {
    for (const auto& l : o.listed_modes) keep(l.frequency, decay_of(l, o.material), l.gain, 0);
    return modes;
  }
  // The wall's shell modes, clamped by the base at the bottom and free at the rim. Struck through
  // its base, the wall rings less than the base; higher orders carry less of the energy.
  for (int n = 2; n <= o.ring_modes; ++n) {
    const double unloaded = shell_mode_frequency(o.material, mid_radius(o), o.wall_thickness, n,
                                                 kClampedFreeBeta / o.height);
    const Loading wall = loading_at(o, pad_damping, unloaded);
    const double f = wall.wall_factor * unloaded;
    keep(f, o.material.decay_rate(f) + wall.held_decay, kWallCoupling / (n - 1), n);
  }
  // The base: a clamped disc's first three modes, struck near its edge.
  constexpr std::array<std::pair<double, double>, 3> kBaseModes{
      {{10.2158, 1.0}, {21.260, 0.4}, {39.771, 0.3}}};
  for (const auto& [lambda2, gain] : kBaseModes) {
    const double base_radius = o.base_radius > 0 ? o.base_radius : o.radius;
    const double unloaded =
        clamped_plate_frequency(o.material, base_radius, o.base_thickness, lambda2);
    const double f = loading_at(o, pad_damping, unloaded).base_factor * unloaded;
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

std::vector<Mode> dense_wall_band(const ObjectSpec& o, double max_frequency_hz,
                                  double contact_loss_factor, double pad_damping) {
  std::vector<Mode> bands;
  if (!o.listed_modes.empty()) return bands;
  const double loss = added_loss_factor(o, contact_loss_factor);
  // Third-octave bands centred on 1000 * 2^(k/3) Hz: per band, how many modes and the sum of
  // gain^2 / decay that pooling must keep.
  constexpr int kBandsPerOctave = 3;
  constexpr int kLowestBand = -15;  // 31 Hz: below every wall mode
  constexpr int kBandCount = 40;    // up to 256 kHz: beyond any recording's Nyquist
  std::array<int, kBandCount> count{};
  std::array<double, kBandCount> energy{}, decay_sum{};
  auto band_of = [&](double f) {
    return static_cast<int>(std::lround(kBandsPerOctave * std::log2(f / 1000.0))) - kLowestBand;
  };
  // Axial orders m: the clamped-free beam's wavenumbers, 1.8751 then (2m - 1) pi / 2 (4.694,
  // 7.855, ...) over the height. Orders n around; each n >= 1 is a pair (cos and sin n theta).
  for (int m = 1;; ++m) {
    const double beta = m == 1 ? kClampedFreeBeta : (2.0 * m - 1.0) * std::numbers::pi / 2.0;
    bool any_below = false;
    double previous = 0;
    for (int n = 0;; ++n) {
      const double unloaded =
          shell_mode_frequency(o.material, mid_radius(o), o.wall_thickness, n, beta / o.height);
      const Loading wall = loading_at(o, pad_damping, unloaded);
      const double f = wall.wall_factor * unloaded;
      // Over n the frequency falls (the membrane term) then rises (bending, as n^4): once rising
      // and above the limit, every higher n is too.
      const bool rising = n > 0 && f > previous;
      previous = f;
      if (f >= max_frequency_hz) {
        if (rising) break;
        continue;
      }
      any_below = true;
      if (m == 1 && n >= 2 && n <= o.ring_modes) continue;  // listed one by one (object_modes)
      const int b = band_of(f);
      if (b < 0 || b >= kBandCount) continue;
      const double sigma = o.material.decay_rate(f) + std::numbers::pi * f * loss + wall.held_decay;
      const int multiplicity = n == 0 ? 1 : 2;
      count[b] += multiplicity;
      // Equipartition: a point drive puts on average the same energy into every mode of a band (the
      // mean mobility is the modes' sum), each with the wall's coupling through the base.
      energy[b] += multiplicity * kWallCoupling * kWallCoupling / sigma;
      decay_sum[b] += multiplicity * sigma;
    }
    if (!any_below || m > 1000) break;
  }
  for (int b = 0; b < kBandCount; ++b) {
    if (count[b] == 0) continue;
    const double centre =
        1000.0 * std::exp2(static_cast<double>(b + kLowestBand) / kBandsPerOctave);
    const double half = std::exp2(0.5 / kBandsPerOctave);
    const double width = centre * (half - 1.0 / half);
    const double density = count[b] / width;  // modes per hertz
    const double overlap = decay_sum[b] / count[b] * density / std::numbers::pi;
    if (overlap < 1.0 || centre >= max_frequency_hz) continue;  // apart: tones, not a band
    const double band_decay = std::numbers::pi * width;
    bands.push_back({centre, band_decay, std::sqrt(band_decay * energy[b]), 0});
  }
  return bands;
}

double plate_modal_density(const Material& m, double area_m2, double thickness_m) {
  const double longitudinal_speed =
      std::sqrt(m.youngs_modulus / (m.density * (1.0 - m.poisson_ratio * m.poisson_ratio)));
  return area_m2 * std::sqrt(3.0) / (thickness_m * longitudinal_speed);
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
