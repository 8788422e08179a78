// The arm's motors and gears as heard by the microphone.
#pragma once

#include <vector>

#include "sim/contact_trace.h"
#include "sim/sim_config.h"
#include "sim/sound_noise.h"

namespace echoplan::sim {

// The arm's motors and gears: broadband noise (a band around rec.motor_noise_hz) at
// rec.motor_noise_gain per rad/s of the joints' summed speed, following it with time constants
// rec.motor_attack_s (rising) and rec.motor_release_s (dying away after the arm stops); added to
// `out` at rec.sample_rate.
void add_motor_noise(const ContactTrace& trace, const RecordingConfig& rec, NoiseSource& noise,
                     std::vector<float>& out);

}  // namespace echoplan::sim
