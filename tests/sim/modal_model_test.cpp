#include "sim/modal_model.h"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>

#include "sim/recording.h"

namespace echoplan::sim {
namespace {

Material ceramic() { return {"ceramic", 2700, 7.2e10, 0.19, 6, 1e-7}; }

// A cylinder_shell object: sizes in metres, mass in kilograms.
struct ShellSizes {
  double radius, height, wall, base, mass, contact_radius;
  int ring_modes;
};
ObjectSpec shell(const char* name, const ShellSizes& s, const Material& material) {
  ObjectSpec o;
  o.name = name;
  o.radius = s.radius;
  o.height = s.height;
  o.wall_thickness = s.wall;
  o.base_thickness = s.base;
  o.shell_mass = s.mass;
  o.material = material;
  o.contact_radius = s.contact_radius;
  o.ring_modes = s.ring_modes;
  return o;
}

ObjectSpec mug() { return shell("mug", {0.04, 0.1, 0.005, 0.006, 0.3, 0.004, 3}, ceramic()); }

TEST(ModalModel, RayleighDecay) {
  // alpha/2 + beta w^2/2 at 1 kHz: 3 + 1e-7 * (2 pi 1000)^2 / 2 = 3 + 1.9739...
  EXPECT_NEAR(ceramic().decay_rate(1000.0),
              3.0 + 1e-7 * std::pow(2 * std::numbers::pi * 1000, 2) / 2, 1e-12);
}

TEST(ModalModel, LongShellReproducesRayleighsRingMode) {
  // A long free cylindrical shell's n = 2 inextensional mode (Rayleigh, "Theory of Sound" 233;
  // Blevins, "Formulas for Natural Frequency and Mode Shape", table 12-2): f = h / (2 pi R^2) c_b n
  // (n^2 - 1) / sqrt(n^2 + 1), worked by hand for ceramic, R = 0.04 m, h = 0.005 m: c_b =
  // sqrt(7.2e10 / (12 * 2700 * (1 - 0.19^2))) = 1518.37 m/s, f_2 = 2026.35 Hz. Within 2%.
  EXPECT_NEAR(shell_mode_frequency(ceramic(), 0.04, 0.005, 2, 0.0), 2026.35, 0.02 * 2026.35);
  // n = 3: 24 / sqrt(10) against 6 / sqrt(5), ratio 2.8284.
  EXPECT_NEAR(shell_mode_frequency(ceramic(), 0.04, 0.005, 3, 0.0), 2026.35 * 2.8284,
              0.02 * 2026.35 * 2.8284);
  // A short shell clamped at its base is stiffened by stretching: higher than the ring alone.
  EXPECT_GT(shell_mode_frequency(ceramic(), 0.04, 0.005, 2, 1.875 / 0.1), 1.1 * 2026.35);
}

TEST(ModalModel, ClampedPlateReproducesLeissasFundamental) {
  // Leissa, "Vibration of Plates" (1969), table 2.1: lambda^2 = 10.2158 for a clamped circular
  // plate's fundamental, f = lambda^2 / (2 pi a^2) sqrt(D / (rho h)), D = E h^3 / (12 (1 - nu^2));
  // worked by hand for ceramic, a = 0.1 m, h = 2 mm: D = 49.80 N m, f = 493.74 Hz. Within 2%.
  EXPECT_NEAR(clamped_plate_frequency(ceramic(), 0.1, 0.002, 10.2158), 493.74, 0.02 * 493.74);
}

TEST(ModalModel, PlatePointImpedanceIsCremerAndHecklsInfinitePlate) {
  // 8 sqrt(B m''), worked by hand for a 25 mm MDF top (E 3.5 GPa, nu 0.25, 750 kg/m^3):
  // B = 3.5e9 * 0.025^3 / (12 * 0.9375) = 4861.1 N m, m'' = 18.75 kg/m^2, Z = 8 * 301.90 = 2415.2.
  const Material mdf{"mdf", 750, 3.5e9, 0.25, 60, 4.5e-6};
  EXPECT_NEAR(plate_point_impedance(mdf, 0.025), 2415.2, 0.5);
  // Twice as thick: B x 8, m'' x 2, Z x 4.
  EXPECT_NEAR(plate_point_impedance(mdf, 0.05), 4 * 2415.2, 2.0);
}

TEST(ModalModel, ObjectModesComeFromShellPlateAndContactLoss) {
  const auto modes = object_modes(mug(), 20000, 0.03);
  ASSERT_GE(modes.size(), 2u);
  EXPECT_EQ(modes[0].azimuthal_order, 2);
  // Decay: the material's own plus pi f eta of the contact.
  EXPECT_NEAR(
      modes[0].decay_per_s,
      ceramic().decay_rate(modes[0].frequency_hz) + std::numbers::pi * modes[0].frequency_hz * 0.03,
      1e-9);
}

TEST(ModalModel, HoldingPadsDampTheWallModesNotTheBase) {
  // A damper c on a mode of modal mass m takes sigma = c / (2 m). The test mug's wall weighs
  // 0.3 * (2 * 0.005 * 0.1) / (2 * 0.005 * 0.1 + 0.04 * 0.006) = 0.241935 kg, a quarter of it
  // 0.060484 kg: 2.4 N s/m adds 2.4 / (2 * 0.060484) = 19.840 1/s to every wall mode.
  const auto free = object_modes(mug(), 20000, 0.0);
  const auto held = object_modes(mug(), 20000, 0.0, 2.4);
  ASSERT_EQ(free.size(), held.size());
  int wall = 0, base = 0;
  for (std::size_t i = 0; i < free.size(); ++i) {
    EXPECT_DOUBLE_EQ(held[i].frequency_hz, free[i].frequency_hz);
    const double added = held[i].decay_per_s - free[i].decay_per_s;
    if (free[i].azimuthal_order >= 2) {
      EXPECT_NEAR(added, 19.840, 0.01) << free[i].frequency_hz;
      ++wall;
    } else {
      EXPECT_EQ(added, 0.0) << free[i].frequency_hz;
      ++base;
    }
  }
  EXPECT_EQ(wall, 2);  // n = 2, 3
  EXPECT_GE(base, 1);
  // Half the mass, twice the loss: the same pads mute a light cup's wall more than a mug's.
  ObjectSpec light = mug();
  light.shell_mass = 0.15;
  EXPECT_NEAR(object_modes(light, 20000, 0.0, 2.4)[0].decay_per_s - free[0].decay_per_s, 2 * 19.840,
              0.02);
}

// A mass fixed on the base lowers the base's modes by sqrt(m / (m + added)); on a loose mount (a
// share 1 / (1 + (f / f_mount)^2) of it follows at f) the kilohertz modes hardly feel it.
TEST(ModalModel, OnlyAMassThatFollowsTheModeLowersIt) {
  constexpr double kEveryMode = 1e6;  // Hz: no mode is dropped by the limit, loaded or not
  const auto bare = object_modes(mug(), kEveryMode, 0.0);
  ObjectSpec rigid = mug();
  rigid.added_masses.push_back({.mass = 0.2, .position = {0, 0, 0.01}});
  ObjectSpec loose = rigid;
  loose.added_masses[0].mount_hz = 50;
  const auto fixed = object_modes(rigid, kEveryMode, 0.0);
  const auto mounted = object_modes(loose, kEveryMode, 0.0);
  ASSERT_EQ(fixed.size(), bare.size());
  ASSERT_EQ(mounted.size(), bare.size());
  // The test mug's base weighs 0.3 - 0.241935 = 0.058065 kg (see
  // HoldingPadsDampTheWallModesNotTheBase).
  const double base_mass = 0.3 - 0.241935;
  int base_modes = 0;
  for (std::size_t i = 0; i < bare.size(); ++i) {
    const double f = bare[i].frequency_hz;
    if (bare[i].azimuthal_order >= 2) {  // the wall: no mass on it
      EXPECT_DOUBLE_EQ(fixed[i].frequency_hz, f);
      EXPECT_DOUBLE_EQ(mounted[i].frequency_hz, f);
      continue;
    }
    ++base_modes;
    EXPECT_NEAR(fixed[i].frequency_hz, f * std::sqrt(base_mass / (base_mass + 0.2)), 1e-3 * f);
    const double following = 0.2 / (1 + (f / 50) * (f / 50));
    EXPECT_NEAR(mounted[i].frequency_hz, f * std::sqrt(base_mass / (base_mass + following)),
                1e-3 * f);
    EXPECT_GT(mounted[i].frequency_hz, 0.999 * f);
  }
  EXPECT_EQ(base_modes, 3);
}

TEST(ModalModel, ClosedTubeRingsAtHalfWavelengthCavity) {
  ObjectSpec can = mug();
  can.height = 0.23;
  can.closed = true;
  const auto modes = object_modes(can, 20000);
  int cavities = 0;
  for (const auto& m : modes)
    if (std::abs(m.frequency_hz - kSpeedOfSound / (2 * 0.23)) < 1e-9) ++cavities;
  EXPECT_EQ(cavities, 1);
  can.closed = false;
  for (const auto& m : object_modes(can, 20000))
    EXPECT_GT(std::abs(m.frequency_hz - kSpeedOfSound / (2 * 0.23)), 1.0);
}

TEST(ModalModel, ListedModesReplaceDerivedOnesAndModesAboveTheLimitAreDropped) {
  ObjectSpec o = mug();
  o.listed_modes = {{500, 1.0, 0}, {1500, 0.5, 40}, {30000, 1.0, 0}};
  const auto modes = object_modes(o, 20000);
  ASSERT_EQ(modes.size(), 2u);
  EXPECT_DOUBLE_EQ(modes[0].frequency_hz, 500);
  EXPECT_DOUBLE_EQ(modes[0].decay_per_s, ceramic().decay_rate(500));
  EXPECT_DOUBLE_EQ(modes[1].decay_per_s, 40);  // listed decay wins over the material's
}

TEST(ModalModel, HertzContactTimeScalesAsMassToTwoFifths) {
  const double e_star = effective_modulus(ceramic(), ceramic());
  // Two identical materials: E* = E / (2 (1 - nu^2)).
  EXPECT_NEAR(e_star, 7.2e10 / (2 * (1 - 0.19 * 0.19)), 1.0);
  const double t1 = hertz_contact_time(0.3, 0.004, e_star, 0.1);
  const double t2 = hertz_contact_time(0.6, 0.004, e_star, 0.1);
  EXPECT_NEAR(t2 / t1, std::pow(2.0, 0.4), 1e-12);
  EXPECT_NEAR(hertz_contact_time(0.3, 0.004, e_star, 0.2) / t1, std::pow(2.0, -0.2), 1e-12);
  // The formula's value, by hand: 2.87 * (0.09 / (0.004 * e_star^2 * 0.1))^0.2.
  EXPECT_NEAR(t1, 2.87 * std::pow(0.09 / (0.004 * e_star * e_star * 0.1), 0.2), 1e-15);
}

TEST(ModalModel, HalfSineSpectrumMatchesNumericalFourierTransform) {
  // Independent reference: integrate F(t) = (pi / 2 tau) sin(pi t / tau) e^{-i w t} over [0, tau]
  // with the midpoint rule (20000 points: error ~1e-8 relative).
  const double tau = 0.8e-3;
  for (double f : {0.0, 100.0, 625.0, 1250.0, 2000.0, 5000.0, 11000.0}) {
    const double w = 2 * std::numbers::pi * f;
    std::complex<double> sum = 0;
    const int n = 20000;
    for (int i = 0; i < n; ++i) {
      const double t = (i + 0.5) * tau / n;
      sum += std::numbers::pi / (2 * tau) * std::sin(std::numbers::pi * t / tau) *
             std::polar(1.0, -w * t) * (tau / n);
    }
    EXPECT_NEAR(half_sine_pulse_spectrum(w, tau), std::abs(sum), 1e-6) << f;
  }
}

TEST(ModalModel, SynthesisEnvelopeFollowsTheHalfSineSpectrumsLobes) {
  // Above the first zero (w tau = 3 pi) the exact spectrum's lobes peak near even x = w tau / pi at
  // 1 / (x^2 - 1), the envelope is 1 / sqrt(1 + x^4): their ratio x^2 / (x^2 - 1) is at most 16/15
  // (x = 4), so the exact spectrum stays within 7% of the envelope, and touches it at each lobe.
  const double tau = 1e-3;
  EXPECT_DOUBLE_EQ(hertz_pulse_envelope(0, tau), 1.0);
  for (double x = 3.0; x < 40.0; x += 0.01) {
    const double w = x * std::numbers::pi / tau;
    EXPECT_LE(half_sine_pulse_spectrum(w, tau), hertz_pulse_envelope(w, tau) * 1.07) << x;
  }
  for (int x = 4; x < 40; x += 2) {
    const double w = x * std::numbers::pi / tau;
    EXPECT_GE(half_sine_pulse_spectrum(w, tau), hertz_pulse_envelope(w, tau)) << x;
  }
  // A longer contact is duller: less at 3 kHz.
  EXPECT_LT(hertz_pulse_envelope(2 * std::numbers::pi * 3000, 1.2e-3),
            hertz_pulse_envelope(2 * std::numbers::pi * 3000, 1e-3));
}

// A thin polycarbonate cup (the shipped plastic_cup's wall) whose decay is the same at every
// frequency (Rayleigh alpha only, no contact loss, no pads), so a band's pooled gain tells how many
// modes it holds: gain^2 / band decay = count * 0.6^2 / sigma.
Material flat_damped_polycarbonate() { return {"pc", 1190, 2.4e9, 0.37, 200, 0}; }  // sigma 100/s

ObjectSpec thin_cup() {
  return shell("cup", {0.042, 0.11, 0.0008, 0.0012, 0.018, 0.0005, 5}, flat_damped_polycarbonate());
}

TEST(ModalModel, PlateModalDensityIsFourMassesTimesItsMeanMobility) {
  // Cremer & Heckl: a plate's mean point conductance is n(f) / (4 M) and equals the infinite
  // plate's 1 / (8 sqrt(B m'')); two textbook formulas, one identity. For 1 m^2 of 1 mm steel.
  const Material steel{"steel", 7850, 2.0e11, 0.29, 5, 8e-8};
  const double area = 1.0, h = 0.001, mass = 7850 * h * area;
  EXPECT_NEAR(plate_modal_density(steel, area, h), 4 * mass / plate_point_impedance(steel, h),
              1e-9 * plate_modal_density(steel, area, h));
  // By hand: c_L = sqrt(2e11 / (7850 (1 - 0.29^2))) = 5274.5 m/s; n = sqrt(3) / (0.001 c_L).
  EXPECT_NEAR(plate_modal_density(steel, area, h), 0.32838, 0.0005);
}

TEST(ModalModel, DenseBandHoldsAsManyModesAsTheWallsPlateAboveItsRingFrequency) {
  // Above its ring frequency c_L / (2 pi R) (5.8 kHz for the cup) a cylindrical shell's modal
  // density approaches a flat plate's of the same area and thickness (Szechenyi 1971). The bands'
  // pooled gains give the modes counted from the shell's own frequencies (sigma = 100/s at every
  // frequency): over the bands from 8 to 16 kHz they must hold the plate's count within 20%.
  const ObjectSpec cup = thin_cup();
  const double sigma = 100.0;
  const auto bands = dense_wall_band(cup, 19845);
  const double area = 2 * std::numbers::pi * (cup.radius - cup.wall_thickness / 2) * cup.height;
  const double density = plate_modal_density(cup.material, area, cup.wall_thickness);
  double counted = 0, expected = 0;
  for (const Mode& b : bands) {
    if (b.frequency_hz < 7000 || b.frequency_hz > 17000) continue;
    const double width = b.decay_per_s / std::numbers::pi;  // the band's width in hertz
    counted += b.gain * b.gain / b.decay_per_s * sigma / (0.6 * 0.6);
    expected += density * width;
  }
  ASSERT_GT(expected, 0);
  EXPECT_NEAR(counted / expected, 1.0, 0.2) << counted << " modes, plate " << expected;
}

TEST(ModalModel, ThinWallsModesOverlapIntoABandAThickMugsStayApart) {
  // Modal overlap f eta n(f) = sigma n / pi: the cup's 0.8 mm wall held by the pads (a few hundred
  // per second on 18 g) has dozens of modes per kilohertz, so they overlap from about 1 kHz; the
  // 5 mm ceramic mug's have ~1-2 per kilohertz and its modes stay apart far above 10 kHz.
  ObjectSpec cup = thin_cup();
  cup.material = {"polycarbonate", 1190, 2.4e9, 0.37, 1, 1.6e-6};
  const auto cup_bands = dense_wall_band(cup, 19845, 0.03, kFingerPadDamping);
  ASSERT_FALSE(cup_bands.empty());
  EXPECT_LT(cup_bands.front().frequency_hz, 1300);
  for (const Mode& b : dense_wall_band(mug(), 19845, 0.03, kFingerPadDamping))
    EXPECT_GT(b.frequency_hz, 12000);
  // Listed modes are what the catalogue says there is: nothing added.
  ObjectSpec listed = cup;
  listed.listed_modes = {{1000, 10, 1}};
  EXPECT_TRUE(dense_wall_band(listed, 19845, 0.03, kFingerPadDamping).empty());
}

TEST(ModalModel, DenseBandLeavesOutTheWallModesListedOneByOne) {
  // n = 2..ring_modes of the first axial order are rendered as modes by object_modes(); the band
  // must not count them again. Their 0.6 * 0.6 / sigma each is what more ring modes take away.
  ObjectSpec fewer = thin_cup(), more = thin_cup();
  fewer.material.alpha = more.material.alpha = 2000;  // sigma 1000/s: every band overlaps
  fewer.ring_modes = 2;
  more.ring_modes = 5;
  auto pooled = [](const std::vector<Mode>& bands) {
    double e = 0;
    for (const Mode& b : bands) e += b.gain * b.gain / b.decay_per_s;
    return e;
  };
  // n = 3, 4, 5 of the first axial order, each a cos and sin pair, at sigma = 1000/s.
  const double removed =
      pooled(dense_wall_band(fewer, 19845)) - pooled(dense_wall_band(more, 19845));
  EXPECT_NEAR(removed, 6 * 0.6 * 0.6 / 1000.0, 1e-9);
}

}  // namespace
}  // namespace echoplan::sim
