// Sliding: the friction excitation read off a fractal surface profile at the trace's sliding
// speed, and how it drives the object's, the wall's and the table's modes.
#pragma once

#include <cstddef>
#include <vector>

#include "sim/contact_trace.h"
#include "sim/modal_model.h"
#include "sim/sound_modes.h"
#include "sim/sound_noise.h"

namespace echoplan::sim {

// The friction excitation at audio rate: normal force times the profile's change as it passes the
// contact at the sliding speed (per-step physics values interpolated linearly).
std::vector<float> friction_excitation(const ContactTrace& trace, int rate, std::size_t frames,
                                       double gain, NoiseSource& noise);

// Sets the continuous (friction) gains of the object's, the table's and the wall's dense-band
// drives. Roughness noise is a velocity source between two bodies, so the imposed velocity splits
// between the object (a mass `object_mass` on the contact) and the table top (its point impedance
// `table_impedance`, N s/m) like a source across two impedances in series (Cremer & Heckl).
void set_friction_drives(double object_mass, double table_impedance, double table_coincidence_hz,
                         double wall_coincidence_hz, const std::vector<Mode>& object_modes,
                         const std::vector<Mode>& table_modes, const std::vector<Mode>& dense_modes,
                         std::vector<ModeDrive>& object_drives,
                         std::vector<ModeDrive>& table_drives,
                         std::vector<ModeDrive>& dense_drives);

}  // namespace echoplan::sim
