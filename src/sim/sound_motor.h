// The arm's motors and gears as heard by the microphone.
#pragma once

#include <vector>

#include "sim/contact_trace.h"
#include "sim/sound_noise.h"

namespace echoplan::sim {

// The arm's motors and gears: broadband noise (a band around kMotorHz) whose amplitude follows the
// joints' speed, rising over kMotorAttack and dying away over kMotorRelease after the arm stops.
void add_motor_noise(const ContactTrace& trace, int rate, double gain, NoiseSource& noise,
                     std::vector<float>& out);

}  // namespace echoplan::sim
