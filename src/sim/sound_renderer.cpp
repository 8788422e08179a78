#include "sim/sound_renderer.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "sim/sound_friction.h"
#include "sim/sound_microphone.h"
#include "sim/sound_modes.h"
#include "sim/sound_motor.h"
#include "sim/sound_noise.h"
#include "sim/sound_room.h"

namespace echoplan::sim {

SoundRenderer::SoundRenderer(const ObjectSpec& object, const TableSpec& table,
                             const SimConfig& config)
    : object_(object),
      config_(config),
      object_modes_(sim::object_modes(object, 0.45 * config.recording.sample_rate,
                                      table.contact_loss_factor, kFingerPadDamping)),
      table_modes_(sim::table_modes(table)),
      dense_modes_(sim::dense_wall_band(object, 0.45 * config.recording.sample_rate,
                                        table.contact_loss_factor, kFingerPadDamping)),
      table_surface_(table.surface),
      contact_modulus_(effective_modulus(object.material, table.surface)),
      table_coincidence_hz_(coincidence_frequency(table.material, table.thickness)),
      wall_coincidence_hz_(object.wall_thickness > 0
                               ? coincidence_frequency(object.material, object.wall_thickness)
                               : 0),
      table_impedance_(plate_point_impedance(table.material, table.thickness)) {
  std::erase_if(table_modes_, [&](const Mode& m) {
    return m.frequency_hz >= 0.45 * config.recording.sample_rate;
  });
}

double SoundRenderer::contact_ring_decay(const Impact& impact) const {
  const double ring_hz = 0.5 / contact_time(impact);
  // The Hertzian spring's strain energy sits in both bodies in proportion to their compliances
  // (1 - nu^2) / E, so each loses its share at its own material's rate.
  auto compliance = [](const Material& m) {
    return (1.0 - m.poisson_ratio * m.poisson_ratio) / m.youngs_modulus;
  };
  const double surface_share =
      compliance(table_surface_) / (compliance(table_surface_) + compliance(object_.material));
  return surface_share * table_surface_.decay_rate(ring_hz) +
         (1.0 - surface_share) * object_.material.decay_rate(ring_hz) +
         kFingerPadDamping / (2.0 * impact.effective_mass);
}

double SoundRenderer::contact_time(const Impact& impact) const {
  return hertz_contact_time(impact.effective_mass, object_.contact_radius, contact_modulus_,
                            impact.normal_speed);
}

std::vector<float> SoundRenderer::dry_sound(const ContactTrace& trace, std::size_t frames,
                                            NoiseSource& noise) const {
  const auto& rec = config_.recording;
  const int rate = rec.sample_rate;
  std::vector<ModeDrive> object_drives(object_modes_.size()), table_drives(table_modes_.size());
  std::vector<float> dry(frames, 0.0f);
  for (const Impact& struck : trace.impacts) {
    const auto at = static_cast<std::size_t>(std::lround(struck.time_s * rate));
    if (at >= frames) continue;
    // A mass on a loose mount (AddedMass::mount_hz) stays still during a contact far shorter than
    // its mount's period: the impact moves, and its sound feels, only what follows. The contact's
    // frequency is taken with every mass rigid (a following mass would lengthen it); the physics'
    // effective mass is scaled by the rigid-body ratio of what moves to the whole.
    const ObjectSpec moving = object_.moving_at(0.5 / contact_time(struck));
    const double azimuth = struck.contacts.empty() ? 0.0 : struck.contacts.front().azimuth_rad;
    const double moved_mass = moving.total_mass();
    Impact impact = struck;
    impact.effective_mass *=
        moving.rim_effective_mass(azimuth) / object_.rim_effective_mass(azimuth);
    const double tau = contact_time(impact);
    // The object's modes respond to an impulse inversely to the mass it moves.
    const double object_mode_scale = kReferenceModalMass / moved_mass;
    add_impact_impulses(impact, at, tau, rec, object_modes_, object_mode_scale, table_modes_,
                        table_coincidence_hz_, object_drives, table_drives);
    add_contact_ring(rec.contact_ring_gain, impact.effective_mass * impact.normal_speed, tau,
                     contact_ring_decay(impact), at, rate, dry);
  }
  const std::vector<float> friction = friction_excitation(
      trace, rate, frames, rec.friction_gain,
      {object_.friction, rec.friction_load_exponent, rec.friction_reference_force_n}, noise);
  std::vector<ModeDrive> dense_drives(dense_modes_.size());
  set_friction_drives([this](double f) { return object_.mass_at(f); }, table_impedance_,
                      table_coincidence_hz_, wall_coincidence_hz_, object_modes_, table_modes_,
                      dense_modes_, object_drives, table_drives, dense_drives);
  render_mode_banks({{&object_modes_, &object_drives},
                     {&table_modes_, &table_drives},
                     {&dense_modes_, &dense_drives}},
                    friction, rate, dry);
  // The rubbing contact itself radiates broadband noise besides ringing the modes.
  for (std::size_t n = 0; n < frames; ++n)
    dry[n] += static_cast<float>(rec.friction_direct_gain) * friction[n];
  add_motor_noise(trace, rec, noise, dry);
  return dry;
}

audio::AudioClip SoundRenderer::render(const ContactTrace& trace, double action_duration_s,
                                       Rng& rng) const {
  const auto& rec = config_.recording;
  const int rate = rec.sample_rate;
  const double seconds = std::max(rec.duration_s, action_duration_s + 0.2);
  const auto frames = static_cast<std::size_t>(std::lround(seconds * rate));

  // What varies from recording to recording: where the microphone stand was, how loud the room was.
  const auto& var = config_.variability;
  const double mic_offset = var.microphone_distance.draw(rng);
  const double noise_db = rec.noise_dbfs + var.background_db.draw(rng);
  NoiseSource noise(rng);
  const std::vector<float> dry = dry_sound(trace, frames, noise);

  // The room: the dry sound plus its reverberant tail, shared by both capsules (they are
  // centimetres apart in the same room).
  const std::vector<float> room = add_room(dry, reverb_taps(config_.room, rate, rng));
  std::array<std::vector<float>, 2> heard =
      capsules_hear(room, config_.microphone, rec, trace.object_position, mic_offset, rate);
  apply_limiter(rec, rate, heard);
  return recorder_output(heard, rec, noise_db, noise);
}

}  // namespace echoplan::sim
