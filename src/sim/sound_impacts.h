// Impacts: what one object-table impact of the contact trace does to the sound. Its momentum is an
// impulse to every object and table mode, weighted by the spectrum of its Hertz force pulse (and,
// for ring modes, by the rim contact pattern); the contact itself rings on its Hertzian spring.
#pragma once

#include <cstddef>
#include <vector>

#include "sim/contact_trace.h"
#include "sim/modal_model.h"
#include "sim/sim_config.h"
#include "sim/sound_modes.h"

namespace echoplan::sim {

// An object's modes answer a force impulse with a velocity inversely proportional to their modal
// mass (about the object's mass): a heavy mug rings less for the same push than a light cup.
// Relative to this mass (kg). A normalisation, not a tuned value: another reference mass scales
// every object's modes alike, which recording.contact_ring_gain, recording.table_impact_gain and
// recording.output_gain (tuned against the lab's recordings with this value) would absorb.
inline constexpr double kReferenceModalMass = 0.06;

// The envelope of a Hertz pulse's spectrum used for synthesis: 1 / sqrt(1 + (omega tau / pi)^4).
// It follows the half-sine spectrum's fall-off (1 at low frequency, (pi / omega tau)^2 above)
// without its exact zeros, which a real, not exactly half-sine, pulse does not have.
double hertz_pulse_envelope(double omega, double duration_s);

// How strongly a contact pattern drives ring mode n: floor + (1 - floor) |sum_i f_i e^{i n
// theta_i}| / sum_i f_i. A single point drives it fully; contacts spread evenly round the rim (a
// flat landing) cancel, down to `floor` (recording.ring_mode_floor: real objects are not perfectly
// round, so every ring mode hears a hit).
double ring_excitation(const std::vector<RimContact>& contacts, int order, double floor);

// Adds `impact` (at sample `at`, Hertz contact time `tau`) to the drives of the object's modes
// (scaled by `object_mode_scale`, kReferenceModalMass / the object's mass) and of the table's
// (times rec.table_impact_gain; they radiate as a plate with coincidence frequency
// `table_coincidence_hz`): an impulse of
// momentum m_eff v weighted by the pressure its force pulse radiates at the mode's frequency
// (dipole radiation: omega times the pulse spectrum) and, for ring modes, by the rim contact
// pattern (rec.ring_mode_floor).
void add_impact_impulses(const Impact& impact, std::size_t at, double tau,
                         const RecordingConfig& rec, const std::vector<Mode>& object_modes,
                         double object_mode_scale, const std::vector<Mode>& table_modes,
                         double table_coincidence_hz, std::vector<ModeDrive>& object_drives,
                         std::vector<ModeDrive>& table_drives);

// The pressure the contact radiates directly (the object and the table surface accelerated as a
// whole: dipole radiation, proportional to dF/dt). The impact is the first half-cycle of the object
// bouncing on the contact's Hertzian spring (its period 2 tau, tau the Hertz contact time); the
// hand holds the object pressed onto the table after the strike, so the object does not fly off
// and the oscillation rings on, losing energy in the strained surface and object and into the
// finger pads that hold it (SoundRenderer::contact_ring_decay): `decay_per_s`. Its dF/dt is a
// cosine at 1 / (2 tau) under that decay: why a strike is a short tonal thud near 500 Hz for a
// heavy mug and near 800 Hz for a light cup (the lab's 560 and 904 Hz), and why the added mass of a
// weighted object lowers it (tau ~ m^0.4). Its level is `gain` (recording.contact_ring_gain) times
// the momentum's, relative to the modes'.
void add_contact_ring(double gain, double momentum, double tau, double decay_per_s, std::size_t at,
                      int rate, std::vector<float>& out);

}  // namespace echoplan::sim
