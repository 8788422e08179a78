#include "sim/sound_motor.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace echoplan::sim {

void add_motor_noise(const ContactTrace& trace, const RecordingConfig& rec, NoiseSource& noise,
                     std::vector<float>& out) {
  const int rate = rec.sample_rate;
  const double gain = rec.motor_noise_gain;
  if (gain <= 0 || trace.steps == 0 || trace.joint_speed.empty()) return;
  // RBJ band-pass biquad (constant 0 dB peak gain).
  const double w0 = 2.0 * std::numbers::pi * rec.motor_noise_hz / rate;
  const double bandwidth = std::sin(w0) / (2.0 * rec.motor_noise_q);
  const double a0 = 1 + bandwidth;
  const double b0 = bandwidth / a0, b2 = -bandwidth / a0, a1 = -2 * std::cos(w0) / a0,
               a2 = (1 - bandwidth) / a0;
  const double attack = 1.0 - std::exp(-1.0 / (rec.motor_attack_s * rate));
  const double release = 1.0 - std::exp(-1.0 / (rec.motor_release_s * rate));
  double envelope = 0, x1 = 0, x2 = 0, y1 = 0, y2 = 0;
  for (std::size_t n = 0; n < out.size(); ++n) {
    const auto step =
        std::min(static_cast<std::size_t>(static_cast<double>(n) / rate / trace.timestep_s),
                 trace.joint_speed.size() - 1);
    const double speed =
        static_cast<double>(n) / rate < trace.duration_s() ? trace.joint_speed[step] : 0.0;
    envelope += (speed > envelope ? attack : release) * (speed - envelope);
    if (envelope < 1e-6 && speed == 0) continue;
    const double x = noise.next();
    const double y = b0 * x + b2 * x2 - a1 * y1 - a2 * y2;
    x2 = x1;
    x1 = x;
    y2 = y1;
    y1 = y;
    out[n] += static_cast<float>(gain * envelope * y);
  }
}

}  // namespace echoplan::sim
