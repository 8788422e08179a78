// The simulated microphone: renders what it hears during one action from the action's contact
// trace, by modal synthesis (van den Doel, Kry & Pai 2001).
//
// Signal chain, per recording:
// - impacts: a Hertz contact (duration from effective mass, contact radius, E*, speed) whose
// spectrum
//   weights each mode (the rim contact pattern weights the shell ring modes), radiating directly as
//   the object ringing on its contact spring (the contact ring);
// - sliding: a fractal (1/f^2) surface profile read at the sliding speed (roughness noise);
// - both drive the object's modes and the table's modes (damped resonators), and friction the
//   object's wall where its modes overlap (dense_wall_band: a thin cup hisses); a slide's roughness
//   velocity splits between object and table by their impedances (a heavy object resists it at high
//   frequency and the table takes it); the arm's motors add
//   band noise following the joints' speed;
// - a short room response (the direct sound plus a sparse, exponentially decaying noise tail);
// - two microphone capsules, each with its own delay and 1/r gain from its distance to the object;
// - the recorder's limiter, then background noise. A fixed output gain, no normalisation.
#pragma once

#include <vector>

#include "audio/clip.h"
#include "common/rng.h"
#include "sim/modal_model.h"
#include "sim/simulated_robot.h"

namespace echoplan::sim {

class SimulatedRecorder {
 public:
  // Precomputes the modal banks of `object` and `table` and the contact modulus.
  SimulatedRecorder(const ObjectSpec& object, const TableSpec& table, const SimConfig& config);

  // The stereo clip from the start of the action to its end (at least config.recording.duration_s
  // long; 0.2 s past the action's end if that is longer), at config.recording.sample_rate. The room
  // response, surface profile and noise are drawn from `rng`.
  audio::AudioClip record(const ActionOutcome& outcome, Rng& rng) const;

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
  double object_mode_scale_ =
      1;  // the object's modes' response per unit impulse, relative (1 / mass)
};

// Begins a trial on `robot`, runs `action` as its first action and records it: the placement, the
// outcome and its clip, all from `rng` (so one seed gives one file).
struct Recording {
  ActionOutcome outcome;
  audio::AudioClip clip;
};
Recording simulate_recording(SimulatedRobot& robot, const SimulatedRecorder& recorder,
                             SoundAction action, Rng& rng);

// The envelope of a Hertz pulse's spectrum used for synthesis: 1 / sqrt(1 + (omega tau / pi)^4).
// It follows the half-sine spectrum's fall-off (1 at low frequency, (pi / omega tau)^2 above)
// without its exact zeros, which a real, not exactly half-sine, pulse does not have.
double hertz_pulse_envelope(double omega, double duration_s);

}  // namespace echoplan::sim
