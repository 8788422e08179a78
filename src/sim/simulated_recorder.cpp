#include "sim/simulated_recorder.h"

#include <kiss_fftr.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <memory>
#include <numbers>

namespace echoplan::sim {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
constexpr double kRingGainFloor =
    0.15;  // real objects are not perfectly round: every ring mode hears a hit
constexpr double kTableCoupling = 0.4;  // share of the contact force's effect that rings the table
constexpr double kProfileSpacing =
    2.0e-6;  // m between surface-profile samples (12.5 kHz at 5 cm/s)
constexpr double kReferenceSlideSpeed = 0.05;  // m/s at which friction_gain is calibrated
constexpr double kStaticSpeed =
    1e-4;  // m/s: slower creep is static contact (the solver's drift), silent
constexpr double kTailDecay = 11.5;      // ln(1e5): a mode is rendered until it fell by 100 dB
constexpr double kSourceHeight = 0.02;   // m above the table: where the object radiates from
constexpr double kDirectPathGain = 0.3;  // pressure at 1 m per unit modal amplitude

// One mode's excitation: impulses at given samples plus (optionally) a shared continuous drive.
struct ModeDrive {
  std::vector<std::pair<std::size_t, double>> impulses;  // (sample, amplitude)
  double continuous_gain = 0;                            // times the friction excitation
};

// Renders mode `mode` driven by `drive` into `out` (added): the resonator
// y[n] = 2 r cos(w) y[n-1] - r^2 y[n-2] + sin(w) x[n] has impulse response r^n sin(w (n + 1)).
// `friction_span` is [first, last] sample where the friction excitation is non-zero (first > last:
// none).
void render_mode(const Mode& mode, const ModeDrive& drive, const std::vector<float>& friction,
                 std::pair<std::size_t, std::size_t> friction_span, int rate,
                 std::vector<float>& out) {
  const double w = kTwoPi * mode.frequency_hz / rate;
  const double r = std::exp(-mode.decay_per_s / rate);
  const double a1 = 2.0 * r * std::cos(w), a2 = -r * r, b = std::sin(w);
  const std::size_t n_total = out.size();
  // Render from the first excitation until 100 dB below the last one.
  std::size_t first = n_total, last = 0;
  for (const auto& [at, amp] : drive.impulses) {
    first = std::min(first, at);
    last = std::max(last, at);
  }
  if (drive.continuous_gain != 0 && friction_span.first <= friction_span.second) {
    first = std::min(first, friction_span.first);
    last = std::max(last, friction_span.second);
  }
  if (first >= n_total) return;
  const double tail =
      mode.decay_per_s > 0 ? kTailDecay / mode.decay_per_s * rate : static_cast<double>(n_total);
  const std::size_t end = std::min(n_total, last + static_cast<std::size_t>(tail) + 1);
  std::vector<double> x(end - first, 0.0);
  for (const auto& [at, amp] : drive.impulses) x[at - first] += amp;
  if (drive.continuous_gain != 0)
    for (std::size_t n = first; n < std::min(end, friction.size()); ++n)
      x[n - first] += drive.continuous_gain * friction[n];
  double y1 = 0, y2 = 0;
  for (std::size_t n = first; n < end; ++n) {
    const double y = a1 * y1 + a2 * y2 + b * x[n - first];
    y2 = y1;
    y1 = y;
    out[n] += static_cast<float>(y);
  }
}

// |sum_i f_i e^{i n theta_i}| / sum_i f_i: how strongly a contact pattern drives ring mode n. A
// single point drives it fully; contacts spread evenly round the rim (a flat landing) cancel.
double ring_excitation(const std::vector<RimContact>& contacts, int order) {
  if (order == 0) return 1.0;
  std::complex<double> sum = 0;
  double total = 0;
  for (const auto& c : contacts) {
    sum += c.normal_force * std::polar(1.0, order * c.azimuth_rad);
    total += c.normal_force;
  }
  const double coherent = total > 0 ? std::abs(sum) / total : 1.0;
  return kRingGainFloor + (1.0 - kRingGainFloor) * coherent;
}

// Zero-mean, unit-variance noise: Irwin-Hall sum of four 16-bit uniforms from one 64-bit SplitMix64
// output. The generator is seeded once from the recording's Rng: one engine call per clip instead
// of one per sample, and identical on every platform.
class NoiseSource {
 public:
  explicit NoiseSource(Rng& rng) : state_(rng()) {}
  float next() {
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    const std::uint64_t sum =
        (z & 0xFFFF) + ((z >> 16) & 0xFFFF) + ((z >> 32) & 0xFFFF) + (z >> 48);
    return static_cast<float>((static_cast<double>(sum) / 65536.0 - 2.0) * std::numbers::sqrt3);
  }

 private:
  std::uint64_t state_;
};

// A 1/f^2 surface profile with `count` samples at kProfileSpacing, unit RMS slope per sample: white
// Gaussian-like noise shaped in the frequency domain (amplitude ~ 1/f).
std::vector<float> fractal_profile(std::size_t count, NoiseSource& noise) {
  std::size_t nfft = 2;
  while (nfft < count) nfft *= 2;
  std::vector<kiss_fft_cpx> spectrum(nfft / 2 + 1);
  spectrum[0] = {0, 0};
  for (std::size_t k = 1; k < spectrum.size(); ++k) {
    const float magnitude = 1.0f / static_cast<float>(k);
    spectrum[k] = {magnitude * noise.next(), magnitude * noise.next()};
  }
  std::vector<float> profile(nfft);
  std::unique_ptr<std::remove_pointer_t<kiss_fftr_cfg>, void (*)(void*)> cfg(
      kiss_fftr_alloc(static_cast<int>(nfft), 1, nullptr, nullptr), kiss_fftr_free);
  kiss_fftri(cfg.get(), spectrum.data(), profile.data());
  double slope_energy = 0;
  for (std::size_t i = 1; i < nfft; ++i)
    slope_energy += (profile[i] - profile[i - 1]) * (profile[i] - profile[i - 1]);
  const double scale = 1.0 / std::sqrt(slope_energy / static_cast<double>(nfft - 1));
  for (auto& h : profile) h = static_cast<float>(h * scale);
  profile.resize(count);
  return profile;
}

// The friction excitation at audio rate: normal force times the profile's change as it passes the
// contact at the sliding speed (per-step physics values interpolated linearly).
std::vector<float> friction_excitation(const ContactTrace& trace, int rate, std::size_t frames,
                                       double gain, NoiseSource& noise) {
  std::vector<float> e(frames, 0.0f);
  double distance = 0;
  for (double v : trace.sliding_speed) distance += v * trace.timestep_s;
  if (distance <= 0 || gain == 0) return e;
  const auto profile =
      fractal_profile(static_cast<std::size_t>(distance / kProfileSpacing) + 4, noise);
  const std::size_t n_end = std::min(frames, static_cast<std::size_t>(trace.duration_s() * rate));
  double x = 0;  // m travelled
  double previous_height = profile[0];
  for (std::size_t n = 0; n < n_end; ++n) {
    const double step_pos = static_cast<double>(n) / rate / trace.timestep_s;
    const std::size_t i =
        std::min(static_cast<std::size_t>(step_pos), static_cast<std::size_t>(trace.steps - 1));
    const std::size_t j = std::min(i + 1, static_cast<std::size_t>(trace.steps - 1));
    const double f = step_pos - static_cast<double>(i);
    const double v = trace.sliding_speed[i] * (1 - f) + trace.sliding_speed[j] * f;
    const double force = trace.normal_force[i] * (1 - f) + trace.normal_force[j] * f;
    if (v < kStaticSpeed) continue;
    x += v / rate;
    const double p = std::min(x / kProfileSpacing, static_cast<double>(profile.size() - 2));
    const std::size_t k = static_cast<std::size_t>(p);
    const double height = profile[k] + (profile[k + 1] - profile[k]) * (p - static_cast<double>(k));
    // The profile has unit slope per profile sample, so (height change) * spacing * rate is slope
    // times speed: at the reference speed the drive is gain * force * slope.
    e[n] = static_cast<float>(gain * force * (height - previous_height) * kProfileSpacing * rate /
                              kReferenceSlideSpeed);
    previous_height = height;
  }
  return e;
}

// The room's response after the direct sound, as sparse taps (delay in samples after the direct
// sound, gain relative to it): taps at random times with random signs under an exponential envelope
// reaching -60 dB at rt60 (velvet noise).
std::vector<std::pair<std::size_t, float>> reverb_taps(const RoomConfig& room, int rate, Rng& rng) {
  std::vector<std::pair<std::size_t, float>> taps;
  const int count = static_cast<int>(std::lround(room.taps_per_s * room.length_s));
  const double first_reflection = 0.0025;  // s after the direct sound
  for (int i = 0; i < count; ++i) {
    const double t = first_reflection + (room.length_s - first_reflection) * uniform01(rng);
    const double sign = uniform01(rng) < 0.5 ? -1.0 : 1.0;
    const double envelope = std::pow(10.0, -3.0 * t / room.rt60_s);
    // Scaled so that the tail's energy, not its tap count, is set by reverb_level.
    const double amplitude =
        sign * room.reverb_level * envelope * std::sqrt(1000.0 / room.taps_per_s);
    taps.emplace_back(static_cast<std::size_t>(std::lround(t * rate)),
                      static_cast<float>(amplitude));
  }
  return taps;
}

// out[i + delay] += gain * in[i] over the overlap (vectorises).
void add_delayed(const std::vector<float>& in, std::size_t delay, float gain,
                 std::vector<float>& out) {
  if (delay >= out.size()) return;
  const std::size_t n = std::min(in.size(), out.size() - delay);
  float* o = out.data() + delay;
  const float* x = in.data();
  for (std::size_t i = 0; i < n; ++i) o[i] += gain * x[i];
}

}  // namespace

double hertz_pulse_envelope(double omega, double duration_s) {
  const double x = omega * duration_s / std::numbers::pi;
  return 1.0 / std::sqrt(1.0 + x * x * x * x);
}

SimulatedRecorder::SimulatedRecorder(const ObjectSpec& object, const TableSpec& table,
                                     const SimConfig& config)
    : object_(object),
      config_(config),
      object_modes_(sim::object_modes(object, 0.45 * config.recording.sample_rate)),
      table_modes_(sim::table_modes(table)),
      contact_modulus_(effective_modulus(object.material, table.material)) {
  std::erase_if(table_modes_, [&](const Mode& m) {
    return m.frequency_hz >= 0.45 * config.recording.sample_rate;
  });
}

double SimulatedRecorder::contact_time(const Impact& impact) const {
  return hertz_contact_time(impact.effective_mass, object_.contact_radius, contact_modulus_,
                            impact.normal_speed);
}

audio::AudioClip SimulatedRecorder::record(const ActionOutcome& outcome, Rng& rng) const {
  const auto& rec = config_.recording;
  const int rate = rec.sample_rate;
  const double seconds = std::max(rec.duration_s, outcome.duration_s + 0.2);
  const auto frames = static_cast<std::size_t>(std::lround(seconds * rate));
  const ContactTrace& trace = outcome.trace;

  // Per-mode drives: each impact is an impulse of momentum m_eff v weighted by the pulse spectrum
  // at the mode's frequency and, for ring modes, by the rim contact pattern.
  std::vector<ModeDrive> object_drives(object_modes_.size()), table_drives(table_modes_.size());
  for (const Impact& impact : trace.impacts) {
    const auto at = static_cast<std::size_t>(std::lround(impact.time_s * rate));
    if (at >= frames) continue;
    const double momentum = impact.effective_mass * impact.normal_speed;
    const double tau = contact_time(impact);
    for (std::size_t k = 0; k < object_modes_.size(); ++k) {
      const Mode& m = object_modes_[k];
      const double amp = momentum * m.gain * hertz_pulse_envelope(kTwoPi * m.frequency_hz, tau) *
                         ring_excitation(impact.contacts, m.azimuthal_order);
      object_drives[k].impulses.emplace_back(at, amp);
    }
    for (std::size_t k = 0; k < table_modes_.size(); ++k) {
      const Mode& m = table_modes_[k];
      table_drives[k].impulses.emplace_back(
          at,
          kTableCoupling * momentum * m.gain * hertz_pulse_envelope(kTwoPi * m.frequency_hz, tau));
    }
  }
  NoiseSource noise(rng);
  const std::vector<float> friction =
      friction_excitation(trace, rate, frames, rec.friction_gain, noise);
  for (std::size_t k = 0; k < object_modes_.size(); ++k)
    object_drives[k].continuous_gain = object_modes_[k].gain;
  for (std::size_t k = 0; k < table_modes_.size(); ++k)
    table_drives[k].continuous_gain = kTableCoupling * table_modes_[k].gain;

  std::pair<std::size_t, std::size_t> friction_span{frames, 0};
  for (std::size_t n = 0; n < friction.size(); ++n)
    if (friction[n] != 0.0f) {
      friction_span.first = std::min(friction_span.first, n);
      friction_span.second = n;
    }

  std::vector<float> dry(frames, 0.0f);
  for (std::size_t k = 0; k < object_modes_.size(); ++k)
    render_mode(object_modes_[k], object_drives[k], friction, friction_span, rate, dry);
  for (std::size_t k = 0; k < table_modes_.size(); ++k)
    render_mode(table_modes_[k], table_drives[k], friction, friction_span, rate, dry);

  // The room: the dry sound plus its reverberant tail, shared by both capsules (they are
  // centimetres apart in the same room).
  std::vector<float> room = dry;
  for (const auto& [delay, gain] : reverb_taps(config_.room, rate, rng))
    add_delayed(dry, delay, gain, room);

  // Two capsules either side of the microphone position along y; each hears the room's sound with
  // its own delay and 1/r gain, plus its own background noise.
  audio::AudioClip clip;
  clip.sample_rate = rate;
  clip.channels = 2;
  clip.samples.assign(frames * 2, 0.0f);
  const auto& mic = config_.microphone;
  const float noise_rms = static_cast<float>(std::pow(10.0, rec.noise_dbfs / 20.0));
  std::vector<float> heard(frames);
  for (int channel = 0; channel < 2; ++channel) {
    const double offset = (channel == 0 ? 0.5 : -0.5) * mic.capsule_spacing;
    const double dx = mic.position[0] - trace.object_position[0];
    const double dy = mic.position[1] + offset - trace.object_position[1];
    const double dz = mic.position[2] - (trace.object_position[2] + kSourceHeight);
    const double distance = std::max(0.05, std::sqrt(dx * dx + dy * dy + dz * dz));
    std::fill(heard.begin(), heard.end(), 0.0f);
    add_delayed(room, static_cast<std::size_t>(std::lround(distance / kSpeedOfSound * rate)),
                static_cast<float>(rec.output_gain * kDirectPathGain / distance), heard);
    const float full_scale_max = 32767.0f / 32768.0f;
    for (std::size_t i = 0; i < frames; ++i)
      clip.samples[2 * i + channel] =
          std::clamp(heard[i] + noise_rms * noise.next(), -1.0f, full_scale_max);
  }
  return clip;
}

Recording simulate_recording(SimulatedRobot& robot, const SimulatedRecorder& recorder,
                             const std::string& action, Rng& rng) {
  Recording r;
  robot.reset_trial(rng);
  r.outcome = robot.execute(action, rng);
  r.clip = recorder.record(r.outcome, rng);
  return r;
}

}  // namespace echoplan::sim
