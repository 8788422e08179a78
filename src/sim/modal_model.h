// The vibration modes of objects and the table, and the Hertz contact that excites them
// (van den Doel, Kry & Pai 2001; contact mechanics after Johnson, "Contact Mechanics", 1985).
//
// Pure functions of catalogue data: no state, no randomness.
#pragma once

#include <vector>

#include "sim/catalogue.h"

namespace echoplan::sim {

inline constexpr double kSpeedOfSound = 343.0;  // m/s, air at 20 degrees C

// One mode of a modal bank. Output of a unit impulse: gain * exp(-decay t) * sin(2 pi frequency t).
struct Mode {
  double frequency_hz = 0;  // > 0
  double decay_per_s = 0;   // >= 0
  double gain = 1;          // relative amplitude for a unit force at the reference point
  int azimuthal_order =
      0;  // n of a shell ring mode (cos n theta around the axis); 0 = axisymmetric
};

// The object's modes below `max_frequency_hz`: the listed ones, or derived from geometry: shell
// ring modes n = 2..ring_modes (Love's inextensional ring-bending frequencies for a thin cylinder,
// f_n = h/(2 pi R^2) sqrt(E / (12 rho (1 - nu^2))) n (n^2 - 1) / sqrt(n^2 + 1)), the base plate's
// first mode (clamped disc, lambda^2 = 10.21), and for a closed tube its air cavity at c / 2L.
// Decay from the material's Rayleigh damping unless listed.
std::vector<Mode> object_modes(const ObjectSpec& object, double max_frequency_hz);

// The table's listed modes, decaying with its material's Rayleigh damping unless listed otherwise.
std::vector<Mode> table_modes(const TableSpec& table);

// Effective contact modulus E* (Pa): 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2.
double effective_modulus(const Material& a, const Material& b);

// Hertz contact time (s) of a sphere of radius `radius_m` and mass `mass_kg` hitting a flat at
// `speed_m_s` with effective modulus `e_star_pa`: tau = 2.87 (m^2 / (R E*^2 v))^(1/5).
double hertz_contact_time(double mass_kg, double radius_m, double e_star_pa, double speed_m_s);

// Magnitude of the Fourier transform of a half-sine force pulse of duration `duration_s` and unit
// impulse, at angular frequency `omega` (rad/s). 1 at omega = 0; falls off above omega ~
// pi/duration, which is why longer contacts sound duller.
double half_sine_pulse_spectrum(double omega, double duration_s);

}  // namespace echoplan::sim
