#include "sim/sound_motor.h"

#include <algorithm>
#include <cmath>

namespace echoplan::sim {

void add_motor_noise(const ContactTrace& trace, const RecordingConfig& rec, NoiseSource& noise,
                     std::vector<float>& out) {
  const int rate = rec.sample_rate;
  const double gain = rec.motor_noise_gain;
  if (gain <= 0 || trace.steps == 0 || trace.joint_speed.empty()) return;
  BandPass band(rec.motor_noise_hz, rec.motor_noise_q, rate);
  const double attack = 1.0 - std::exp(-1.0 / (rec.motor_attack_s * rate));
  const double release = 1.0 - std::exp(-1.0 / (rec.motor_release_s * rate));
  double envelope = 0;
  for (std::size_t n = 0; n < out.size(); ++n) {
    const auto step =
        std::min(static_cast<std::size_t>(static_cast<double>(n) / rate / trace.timestep_s),
                 trace.joint_speed.size() - 1);
    const double speed =
        static_cast<double>(n) / rate < trace.duration_s() ? trace.joint_speed[step] : 0.0;
    envelope += (speed > envelope ? attack : release) * (speed - envelope);
    if (envelope < 1e-6 && speed == 0) continue;
    out[n] += static_cast<float>(gain * envelope * band.filter(noise.next()));
  }
}

}  // namespace echoplan::sim
