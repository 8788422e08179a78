#include "sim/sound_friction.h"

#include <kiss_fftr.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <type_traits>

namespace echoplan::sim {

namespace {

// m between surface-profile samples: the profile's resolution (12.5 kHz at 5 cm/s). Numerical, not
// tuned.
constexpr double kProfileSpacing = 2.0e-6;
// m/s at which recording.friction_gain is calibrated: a normalisation (the report's 5 cm push).
constexpr double kReferenceSlideSpeed = 0.05;
// m/s: slower creep of a pressed contact is the solver's compliance, silent (docs/simulator.md,
// "What is modelled", friction). A threshold of this simulator, not measured on the lab's surfaces.
constexpr double kStaticSpeed = 2e-3;

// A 1/f^2 surface profile with `count` samples at kProfileSpacing, unit RMS slope per sample: white
// Gaussian-like noise shaped in the frequency domain (amplitude ~ 1/f).
std::vector<float> fractal_profile(std::size_t count, NoiseSource& noise) {
  std::size_t nfft = 2;
  while (nfft < count) nfft *= 2;
  std::vector<kiss_fft_cpx> spectrum(nfft / 2 + 1);
  spectrum[0] = {0, 0};
  for (std::size_t k = 1; k < spectrum.size(); ++k) {
    const float magnitude = 1.0f / static_cast<float>(k);
    spectrum[k] = {magnitude * noise.next(), magnitude * noise.next()};
  }
  std::vector<float> profile(nfft);
  std::unique_ptr<std::remove_pointer_t<kiss_fftr_cfg>, void (*)(void*)> cfg(
      kiss_fftr_alloc(static_cast<int>(nfft), 1, nullptr, nullptr), kiss_fftr_free);
  kiss_fftri(cfg.get(), spectrum.data(), profile.data());
  double slope_energy = 0;
  for (std::size_t i = 1; i < nfft; ++i)
    slope_energy += (profile[i] - profile[i - 1]) * (profile[i] - profile[i - 1]);
  const double scale = 1.0 / std::sqrt(slope_energy / static_cast<double>(nfft - 1));
  for (auto& h : profile) h = static_cast<float>(h * scale);
  profile.resize(count);
  return profile;
}

}  // namespace

double FrictionLoad::scale(double normal_force) const {
  if (normal_force <= 0) return 0.0;
  if (exponent == 0) return 1.0;
  return std::pow(coefficient * normal_force / reference_force, exponent);
}

std::vector<float> friction_excitation(const ContactTrace& trace, int rate, std::size_t frames,
                                       double gain, const FrictionLoad& load, NoiseSource& noise) {
  std::vector<float> e(frames, 0.0f);
  double distance = 0;
  for (double v : trace.sliding_speed) distance += v * trace.timestep_s;
  if (distance <= 0 || gain == 0) return e;
  const auto profile =
      fractal_profile(static_cast<std::size_t>(distance / kProfileSpacing) + 4, noise);
  const std::size_t n_end = std::min(frames, static_cast<std::size_t>(trace.duration_s() * rate));
  double x = 0;  // m travelled
  double previous_height = profile[0];
  for (std::size_t n = 0; n < n_end; ++n) {
    const double step_pos = static_cast<double>(n) / rate / trace.timestep_s;
    const std::size_t i =
        std::min(static_cast<std::size_t>(step_pos), static_cast<std::size_t>(trace.steps - 1));
    const std::size_t j = std::min(i + 1, static_cast<std::size_t>(trace.steps - 1));
    const double f = step_pos - static_cast<double>(i);
    const double v = trace.sliding_speed[i] * (1 - f) + trace.sliding_speed[j] * f;
    const double force = trace.normal_force[i] * (1 - f) + trace.normal_force[j] * f;
    if (v < kStaticSpeed) continue;
    x += v / rate;
    const double p = std::min(x / kProfileSpacing, static_cast<double>(profile.size() - 2));
    const std::size_t k = static_cast<std::size_t>(p);
    const double height = profile[k] + (profile[k + 1] - profile[k]) * (p - static_cast<double>(k));
    // The profile has unit slope per profile sample, so (height change) * spacing * rate is slope
    // times speed: at the reference speed the drive is gain * force * slope.
    // Roughness noise: the contact is forced to follow the surfaces' asperities, a velocity source
    // (speed times the profile's slope; Akay 2002, "Acoustics of friction"), scaled by the load
    // (FrictionLoad: how hard the pad has to push the object along).
    e[n] = static_cast<float>(gain * load.scale(force) * (height - previous_height) *
                              kProfileSpacing * rate / kReferenceSlideSpeed);
    previous_height = height;
  }
  return e;
}

void set_friction_drives(const std::function<double(double)>& object_mass_at,
                         double table_impedance, double table_coincidence_hz,
                         double wall_coincidence_hz, const std::vector<Mode>& object_modes,
                         const std::vector<Mode>& table_modes, const std::vector<Mode>& dense_modes,
                         std::vector<ModeDrive>& object_drives,
                         std::vector<ModeDrive>& table_drives,
                         std::vector<ModeDrive>& dense_drives) {
  // Friction drives every mode continuously. Roughness noise is a velocity source (the surfaces are
  // made to follow each other's asperities, see friction_excitation) between two bodies, so the
  // imposed velocity splits between them like a source across two impedances in series (Cremer &
  // Heckl): the object, a mass on the contact (impedance j omega m), takes Z_t / (Z_t + j omega m)
  // of it and the table top (its point impedance Z_t) the rest, j omega m / (Z_t + j omega m). A
  // light cup follows the asperities alone and leaves the table still; a 0.34 kg mug resists above
  // Z_t / (2 pi m) ~ 1.1 kHz, so its 3.7 kHz shell modes are barely driven and the table moves
  // instead. A velocity source sets the modes' velocity whatever their modal mass: no 1 / mass
  // scale here (unlike an impact's impulse). The object radiates as a compact body (dipole: rising
  // with frequency, like the impacts); the table top as a plate, its pressure following its
  // velocity times the square root of its radiation efficiency (plate_radiation), with no dipole
  // factor.
  auto object_share = [&](double f) {
    const double x = 2.0 * std::numbers::pi * f * object_mass_at(f) / table_impedance;
    return 1.0 / std::sqrt(1.0 + x * x);
  };
  for (std::size_t k = 0; k < object_modes.size(); ++k) {
    const Mode& m = object_modes[k];
    object_drives[k].continuous_gain =
        object_share(m.frequency_hz) * m.gain * m.frequency_hz / kReferenceHz;
  }
  // The wall's dense band: bending waves on a thin wall far below its coincidence frequency (53 kHz
  // for the cup's 0.8 mm polycarbonate) radiate as a plate's do (plate_radiation), not as the
  // compact body's dipole.
  for (std::size_t k = 0; k < dense_modes.size(); ++k) {
    const Mode& m = dense_modes[k];
    dense_drives[k].continuous_gain = object_share(m.frequency_hz) * m.gain *
                                      plate_radiation(m.frequency_hz, wall_coincidence_hz);
  }
  for (std::size_t k = 0; k < table_modes.size(); ++k) {
    const Mode& m = table_modes[k];
    const double object = object_share(m.frequency_hz);
    table_drives[k].continuous_gain = std::sqrt(1.0 - object * object) * m.gain *
                                      plate_radiation(m.frequency_hz, table_coincidence_hz);
  }
}

}  // namespace echoplan::sim
