// The simulated microphone's sound: renders one action's contact trace (sim/contact_trace.h) into
// the stereo clip the lab's recorder would have written, by modal synthesis (van den Doel, Kry &
// Pai 2001). It knows the object and the table, never the arm: the trace is all it hears of the
// action.
//
// Signal chain, per clip, each stage in a file of its own:
// - impacts (sound_impacts): a Hertz contact (duration from effective mass, contact radius, E*,
//   speed) whose spectrum weights each mode (the rim contact pattern weights the shell ring modes),
//   radiating directly as the object ringing on its contact spring (the contact ring);
// - sliding (sound_friction): a fractal (1/f^2) surface profile read at the sliding speed
//   (roughness noise), its velocity split between object and table by their impedances;
// - both drive the object's modes, the table's modes and the object's wall where its modes overlap
//   (dense_wall_band: a thin cup hisses), all damped resonators (sound_modes);
// - the arm's motors: band noise following the joints' speed (sound_motor);
// - a short room response: the direct sound plus a sparse, exponentially decaying tail
// (sound_room);
// - two microphone capsules, each with its own delay and 1/r gain from its distance to the object;
//   the recorder's limiter, then background noise (sound_microphone, sound_noise). A fixed output
//   gain, no normalisation.
#pragma once

#include <vector>

#include "audio/clip.h"
#include "common/rng.h"
#include "sim/catalogue.h"
#include "sim/contact_trace.h"
#include "sim/modal_model.h"
#include "sim/sim_config.h"
#include "sim/sound_impacts.h"
#include "sim/sound_noise.h"

namespace echoplan::sim {

class SoundRenderer {
 public:
  // Precomputes the modal banks of `object` and `table` and the contact modulus.
  SoundRenderer(const ObjectSpec& object, const TableSpec& table, const SimConfig& config);

  // The stereo clip of an action that lasted `action_duration_s` (s simulated) and made `trace`:
  // at least config.recording.duration_s long (0.2 s past the action's end if that is longer), at
  // config.recording.sample_rate. The room response, surface profile and noise are drawn from
  // `rng`. An empty trace with duration 0 is the room heard while nothing happens.
  audio::AudioClip render(const ContactTrace& trace, double action_duration_s, Rng& rng) const;

  // The modes rendered (after the recording's Nyquist limit).
  const std::vector<Mode>& object_modes() const { return object_modes_; }
  const std::vector<Mode>& table_modes() const { return table_modes_; }
  // The object's wall where its modes overlap, pooled into bands (dense_wall_band): rubbed, it
  // hisses.
  const std::vector<Mode>& dense_modes() const { return dense_modes_; }

  // Hertz contact time (s) of an impact recorded in a trace, with this object on this table.
  double contact_time(const Impact& impact) const;

  // Decay rate (1/s) of the contact ring an impact starts: the Hertz spring's losses in the table's
  // surface and in the object (each its share of the strain energy) and the holding finger pads'.
  double contact_ring_decay(const Impact& impact) const;

 private:
  // The dry sound at the object: impacts, friction and the motors through the modal banks.
  std::vector<float> dry_sound(const ContactTrace& trace, std::size_t frames,
                               NoiseSource& noise) const;

  ObjectSpec object_;
  SimConfig config_;
  std::vector<Mode> object_modes_;
  std::vector<Mode> table_modes_;
  std::vector<Mode> dense_modes_;
  Material table_surface_;      // the contact presses on it, its ring loses energy into it
  double contact_modulus_ = 0;  // Pa, E* of object material on table material
  double table_coincidence_hz_ = 0;
  double wall_coincidence_hz_ =
      0;                        // of the object's wall, which radiates its dense band as a plate
  double table_impedance_ = 0;  // N s/m, the top's point impedance (plate_point_impedance)
};

}  // namespace echoplan::sim
