// The vibration modes of objects and the table, and the Hertz contact that excites them
// (van den Doel, Kry & Pai 2001; contact mechanics after Johnson, "Contact Mechanics", 1985; shell
// and plate modes after Leissa, "Vibration of Shells" (1973) and "Vibration of Plates" (1969)).
//
// Pure functions of catalogue data: no state, no randomness.
#pragma once

#include <vector>

#include "sim/catalogue.h"

namespace echoplan::sim {

inline constexpr double kSpeedOfSound = 343.0;  // m/s, air at 20 degrees C

// The gripper's rubber finger pads as dampers at audio frequencies (N s/m): a damper c on a body of
// mass m vibrating under it takes energy at the rate c / (2 m) (1/s). Pads a few millimetres of
// rubber thick (stiffness ~1e4-1e5 N/m, loss factor 0.1-0.5: c = eta k / omega ~ 1-5 N s/m at
// 1 kHz). Set to 2.4 from the lab's plastic cup strikes (20 dB down in 15-30 ms on a 10 g
// effective mass); the coffee mug's 45 ms then follows from its mass with nothing changed.
inline constexpr double kFingerPadDamping = 2.4;

// One mode of a modal bank. Output of a unit impulse: gain * exp(-decay t) * sin(2 pi frequency t).
struct Mode {
  double frequency_hz = 0;  // > 0
  double decay_per_s = 0;   // >= 0
  double gain = 1;          // relative amplitude for a unit force at the reference point
  int azimuthal_order =
      0;  // n of a shell ring mode (cos n theta around the axis); 0 = axisymmetric
};

// Natural frequency (Hz) of mode (n around, axial wavenumber k_axial = beta / L along) of a thin
// cylindrical shell of radius `radius_m` and wall `thickness_m`. Donnell's membrane term plus a
// bending term that is Rayleigh's inextensional ring term n^2 (n^2 - 1)^2 / (n^2 + 1) for a long
// shell (k_axial -> 0), with the axial curvature's terms added:
//   Omega^2 = (1 - nu^2) l^4 / (l^2 + n^2)^2 + k [n^2 (n^2 - 1)^2 / (n^2 + 1) + l^4 + 2 l^2 n^2],
//   l = k_axial R, k = h^2 / (12 R^2), f = Omega / (2 pi R) sqrt(E / (rho (1 - nu^2))).
double shell_mode_frequency(const Material& material, double radius_m, double thickness_m, int n,
                            double k_axial);

// Natural frequency (Hz) of a clamped circular plate of radius `radius_m` and thickness
// `thickness_m` for the mode with eigenvalue lambda^2 (Leissa 1969, table 2.1: 10.2158 for (0,1),
// 21.260 for (1,1), 34.877 for (2,1), 39.771 for (0,2)): f = lambda^2 / (2 pi a^2) sqrt(D / (rho
// h)).
double clamped_plate_frequency(const Material& material, double radius_m, double thickness_m,
                               double lambda_squared);

// The object's modes below `max_frequency_hz`: the listed ones, or derived from geometry: the
// wall's shell modes n = 2..ring_modes with the base clamping the wall (the clamped-free beam
// function's first axial wavenumber, 1.875 / height), the base plate's first three clamped modes,
// and for a closed tube its air cavity at c / 2L. Added masses on the base (within a quarter of the
// height) load the base's modes, those higher up the wall's. Decay from the material's damping plus
// `contact_loss_factor` and the added masses' loss factors (sigma += pi f eta), and for the wall's
// modes the holding pads' `pad_damping` (N s/m) on the wall's modal mass (a quarter of the wall's
// mass with any mass added on it: cos n theta around, the clamped-free shape along): sigma +=
// pad_damping / (2 m_modal). The pads hold the wall near its free rim, where its modes move most;
// they do not touch the base.
std::vector<Mode> object_modes(const ObjectSpec& object, double max_frequency_hz,
                               double contact_loss_factor = 0, double pad_damping = 0);

// The object's wall where its modes overlap: the statistical (SEA) rendering of the shell modes
// that object_modes() does not list one by one (every circumferential order n >= 1, axial orders m
// >= 1 with the clamped-free wavenumbers (2m - 1) pi / 2 / height, less n = 2..ring_modes of m = 1;
// n >= 1 counts twice, cos and sin). Above the frequency where neighbouring modes overlap (modal
// overlap factor f eta n(f) = sigma n(f) / pi >= 1, n(f) the modes per hertz, sigma their decay) a
// point-driven structure answers as a smooth band whose level is its mean mobility, not as tones
// (Lyon & DeJong, "Theory and Application of Statistical Energy Analysis"; Cremer & Heckl: a
// plate's mean point conductance 1/(8 sqrt(B m'')) = n(f) / (4 M)). The modes are pooled into
// bands of a third of an octave where they overlap; a band is one resonator as wide as the band
// (decay pi * bandwidth) whose power under white drive is its modes' sum: gain^2 / decay = sum
// over its modes of 0.6^2 / sigma_i (every mode at the wall's coupling through the base, the listed
// wall modes' 0.6: equipartition). Decay as object_modes()' wall modes. Empty for an object with
// listed modes or whose wall's modes stay apart (a thick ceramic mug).
std::vector<Mode> dense_wall_band(const ObjectSpec& object, double max_frequency_hz,
                                  double contact_loss_factor = 0, double pad_damping = 0);

// Shell modes per hertz of a flat plate of area `area_m2` and `thickness_m`
// (frequency-independent): n = area sqrt(3) / (thickness c_L), c_L = sqrt(E / (rho (1 - nu^2)))
// (Cremer & Heckl). A cylindrical shell's density approaches it above its ring frequency.
double plate_modal_density(const Material& material, double area_m2, double thickness_m);

// The table's listed modes and its dense modal field, decaying with its material's damping unless
// listed otherwise.
std::vector<Mode> table_modes(const TableSpec& table);

// Coincidence frequency (Hz) of a plate of `thickness_m`: where its bending waves travel at the
// speed of sound, f_c = c^2 / (2 pi h c_b) with c_b = sqrt(E / (12 rho (1 - nu^2))). Below it a
// plate radiates poorly.
double coincidence_frequency(const Material& material, double thickness_m);

// Driving-point impedance (N s/m) of an infinite plate of `thickness_m`: 8 sqrt(B m''), B = E h^3 /
// (12 (1 - nu^2)) its bending stiffness and m'' = rho h its mass per area (Cremer, Heckl &
// Petersson, "Structure-Borne Sound", the plate's point mobility). Real and independent of
// frequency: a large plate takes a force as a dashpot does.
double plate_point_impedance(const Material& material, double thickness_m);

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
