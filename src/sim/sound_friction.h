// Sliding: the friction excitation read off a fractal surface profile at the trace's sliding
// speed, and how it drives the object's, the wall's and the table's modes.
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

#include "sim/contact_trace.h"
#include "sim/modal_model.h"
#include "sim/sound_modes.h"
#include "sim/sound_noise.h"

namespace echoplan::sim {

// How the friction sound's amplitude follows the load: (mu N / reference_force)^exponent, mu N the
// Coulomb friction force of the object on the table (N the trace's normal force). Exponent 0 is
// pure roughness noise (load-independent, Akay 2002); 0.5 makes the sound power a fixed share of
// the frictional power mu N v, as when the pushed contact sticks and slips (docs/simulator.md,
// "Slides as the lab heard them").
struct FrictionLoad {
  double coefficient = 0;      // mu, the object's against the table
  double exponent = 0;         // in [0, 1]
  double reference_force = 1;  // N, > 0: the force at which the scale is 1
  double scale(double normal_force) const;
};

// The friction excitation at audio rate: the profile's change as it passes the contact at the
// sliding speed, scaled by the load (per-step physics values interpolated linearly).
std::vector<float> friction_excitation(const ContactTrace& trace, int rate, std::size_t frames,
                                       double gain, const FrictionLoad& load, NoiseSource& noise);

// Sets the continuous (friction) gains of the object's, the table's and the wall's dense-band
// drives. Roughness noise is a velocity source between two bodies, so the imposed velocity splits
// between the object (a mass `object_mass_at(f)` on the contact at frequency f) and the table top
// (its point impedance `table_impedance`, N s/m) like a source across two impedances in series
// (Cremer & Heckl).
void set_friction_drives(const std::function<double(double)>& object_mass_at,
                         double table_impedance, double table_coincidence_hz,
                         double wall_coincidence_hz, const std::vector<Mode>& object_modes,
                         const std::vector<Mode>& table_modes, const std::vector<Mode>& dense_modes,
                         std::vector<ModeDrive>& object_drives,
                         std::vector<ModeDrive>& table_drives,
                         std::vector<ModeDrive>& dense_drives);

}  // namespace echoplan::sim
