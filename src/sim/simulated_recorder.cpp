#include "sim/simulated_recorder.h"

#include <kiss_fftr.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <memory>
#include <numbers>

namespace echoplan::sim {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
// An object's modes answer a force impulse with a velocity inversely proportional to their modal
// mass (about the object's mass): a heavy mug rings less for the same push than a light cup.
// Relative to this mass.
constexpr double kReferenceModalMass = 0.06;  // kg
constexpr double kReferenceHz = 1000.0;  // dipole radiation is normalised to 1 at this frequency
constexpr double kPulseGain = 3.0;  // the contact pulse's direct radiation relative to the modes
constexpr double kDirectFriction =
    0.5;                               // the rubbing contact's own radiation relative to the modes
constexpr double kMotorHz = 1200.0;    // centre of the motors' and gears' noise band
constexpr double kMotorQ = 0.7;        // its width (Q of a band-pass: about two octaves)
constexpr double kMotorAttack = 0.15;  // s for the motor noise to follow rising joint speed
constexpr double kMotorRelease = 0.4;  // s for it to die away after the arm slows
constexpr double kLimiterLookahead = 0.001;  // s
constexpr double kRingGainFloor =
    0.15;  // real objects are not perfectly round: every ring mode hears a hit
constexpr double kTableCoupling = 0.25;  // share of an impact's effect that rings the table
constexpr double kProfileSpacing =
    2.0e-6;  // m between surface-profile samples (12.5 kHz at 5 cm/s)
constexpr double kReferenceSlideSpeed = 0.05;  // m/s at which friction_gain is calibrated
constexpr double kStaticSpeed =
    2e-3;  // m/s: slower creep of a pressed contact is the solver's compliance, silent
constexpr double kTailDecay =
    9.2;  // ln(1e4): a mode is rendered until it fell by 80 dB (below the noise floor)
constexpr double kSourceHeight = 0.02;   // m above the table: where the object radiates from
constexpr double kDirectPathGain = 0.3;  // pressure at 1 m per unit modal amplitude

// One mode's excitation: impulses at given samples plus (optionally) a shared continuous drive.
struct ModeDrive {
  std::vector<std::pair<std::size_t, double>> impulses;  // (sample, amplitude)
  double continuous_gain = 0;                            // times the friction excitation
};

// Renders `modes` driven by `drives` into `out` (added). Each mode is the resonator
// y[n] = 2 r cos(w) y[n-1] - r^2 y[n-2] + sin(w) x[n] (impulse response r^n sin(w (n + 1))), from
// its first excitation until kTailDecay below its last. Modes run four at a time in one loop: the
// recursions are independent, so the processor overlaps them (one alone waits on its own latency).
// `friction_span` is [first, last] sample where the friction excitation is non-zero (first > last:
// none).
void render_modes(const std::vector<Mode>& modes, const std::vector<ModeDrive>& drives,
                  const std::vector<float>& friction,
                  std::pair<std::size_t, std::size_t> friction_span,
                  const std::vector<std::size_t>& friction_active, int rate,
                  std::vector<float>& out) {
  constexpr std::size_t kLanes = 4;
  constexpr std::size_t kBlock = 256;
  constexpr double kRestLevel =
      1e-10;  // a resonator this quiet is at rest (~100 dB below the noise floor)
  const std::size_t n_total = std::min(out.size(), friction.size());
  for (std::size_t g = 0; g < modes.size(); g += kLanes) {
    double a1[kLanes] = {}, a2[kLanes] = {}, b[kLanes] = {}, drive[kLanes] = {};
    double y1[kLanes] = {}, y2[kLanes] = {};
    std::size_t first = n_total, end = 0;
    struct Event {
      std::size_t at, lane;
      double amp;
    };
    std::vector<Event> events;
    for (std::size_t lane = 0; lane < kLanes && g + lane < modes.size(); ++lane) {
      const Mode& mode = modes[g + lane];
      const ModeDrive& d = drives[g + lane];
      std::size_t f = n_total, last = 0;
      for (const auto& [at, amp] : d.impulses) {
        if (at >= n_total) continue;
        f = std::min(f, at);
        last = std::max(last, at);
        events.push_back({at, lane, amp});
      }
      if (d.continuous_gain != 0 && friction_span.first <= friction_span.second) {
        f = std::min(f, friction_span.first);
        last = std::max(last, friction_span.second);
        drive[lane] = d.continuous_gain;
      }
      if (f >= n_total) continue;
      const double w = kTwoPi * mode.frequency_hz / rate;
      const double r = std::exp(-mode.decay_per_s / rate);
      a1[lane] = 2.0 * r * std::cos(w);
      a2[lane] = -r * r;
      b[lane] = std::sin(w);
      const double tail = mode.decay_per_s > 0 ? kTailDecay / mode.decay_per_s * rate
                                               : static_cast<double>(n_total);
      first = std::min(first, f);
      end = std::max(end,
                     std::min(n_total, last + static_cast<std::size_t>(std::min(tail, 1e9)) + 1));
    }
    if (first >= end) continue;
    std::sort(events.begin(), events.end(),
              [](const Event& x, const Event& y) { return x.at < y.at; });
    std::size_t next_event = 0;
    for (std::size_t block = first; block < end; block += kBlock) {
      const std::size_t block_end = std::min(end, block + kBlock);
      // A silent stretch (every resonator at rest, no friction, no impulse) is skipped: a strike's
      // modes have died away long before its next scuff.
      bool at_rest = friction_active[block_end] == friction_active[block] &&
                     (next_event >= events.size() || events[next_event].at >= block_end);
      for (std::size_t lane = 0; lane < kLanes && at_rest; ++lane)
        at_rest = std::abs(y1[lane]) < kRestLevel && std::abs(y2[lane]) < kRestLevel;
      if (at_rest) {
        for (std::size_t lane = 0; lane < kLanes; ++lane) y1[lane] = y2[lane] = 0;
        continue;
      }
      for (std::size_t n = block; n < block_end; ++n) {
        double x[kLanes];
        for (std::size_t lane = 0; lane < kLanes; ++lane) x[lane] = drive[lane] * friction[n];
        for (; next_event < events.size() && events[next_event].at == n; ++next_event)
          x[events[next_event].lane] += events[next_event].amp;
        double sum = 0;
        for (std::size_t lane = 0; lane < kLanes; ++lane) {
          const double y = a1[lane] * y1[lane] + a2[lane] * y2[lane] + b[lane] * x[lane];
          y2[lane] = y1[lane];
          y1[lane] = y;
          sum += y;
        }
        out[n] += static_cast<float>(sum);
      }
    }
  }
}

// Pressure amplitude factor of a plate's radiation at `frequency_hz` (1 above `coincidence_hz`):
// below its coincidence frequency a finite plate radiates through its edges and corners only, with
// an efficiency rising about as f / f_c (Maidanik 1962): pressure as its square root.
double plate_radiation(double frequency_hz, double coincidence_hz) {
  return std::sqrt(std::min(1.0, frequency_hz / coincidence_hz));
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
    // Roughness noise: the contact is forced to follow the surfaces' asperities, a velocity source
    // (speed times the profile's slope) that does not depend on the load once the surfaces touch
    // (Akay 2002, "Acoustics of friction"): a heavy object slides no louder than a light one.
    const double touching = force > 0 ? 1.0 : 0.0;
    e[n] = static_cast<float>(gain * touching * (height - previous_height) * kProfileSpacing *
                              rate / kReferenceSlideSpeed);
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

// `room` = `dry` plus every tap's delayed copy, computed a block of output at a time so the block
// stays in cache while all taps are added (taps in the same order for every sample, so the sums are
// exactly those of adding one whole delayed copy after another).
std::vector<float> add_room(const std::vector<float>& dry,
                            const std::vector<std::pair<std::size_t, float>>& taps) {
  constexpr std::size_t kBlock = 4096;
  std::vector<float> room = dry;
  const std::size_t frames = dry.size();
  for (std::size_t start = 0; start < frames; start += kBlock) {
    const std::size_t end = std::min(frames, start + kBlock);
    float* o = room.data();
    for (const auto& [delay, gain] : taps) {
      if (delay >= end) continue;
      const std::size_t from = std::max(start, delay);
      const float* x = dry.data() + (from - delay);
      for (std::size_t i = from; i < end; ++i) o[i] += gain * x[i - from];
    }
  }
  return room;
}

// The pressure the contact radiates directly (the object and the table surface accelerated as a
// whole: dipole radiation, proportional to dF/dt). The impact is the first half-cycle of the object
// bouncing on the contact's Hertzian spring (its period 2 tau, tau the Hertz contact time); the
// hand holds the object pressed onto the table after the strike, so the object does not fly off
// and the oscillation rings on, losing energy in the strained surface and object and into the
// finger pads that hold it (SimulatedRecorder::contact_ring_decay): `decay_per_s`. Its dF/dt is a
// cosine at 1 / (2 tau) under that decay: why a strike is a short tonal thud near 500 Hz for a
// heavy mug and near 800 Hz for a light cup (the lab's 560 and 904 Hz), and why the added mass of a
// weighted object lowers it (tau ~ m^0.4).
void add_contact_ring(double momentum, double tau, double decay_per_s, std::size_t at, int rate,
                      std::vector<float>& out) {
  const double scale = kPulseGain * momentum * std::numbers::pi / (tau * kTwoPi * kReferenceHz);
  const double omega = std::numbers::pi / tau;
  const auto length = static_cast<std::size_t>(std::ceil(kTailDecay / decay_per_s * rate));
  // cos(omega t) e^(-decay t) as a two-pole recursion (exact for the sampled sinusoid).
  const double r = std::exp(-decay_per_s / rate), w = omega / rate;
  double c1 = std::cos(0.5 * w) * std::exp(-0.5 * decay_per_s / rate), c2 = 0;  // n = 0 value
  const double a1 = 2.0 * r * std::cos(w), a2 = -r * r;
  double y_prev = std::cos(-0.5 * w) * std::exp(0.5 * decay_per_s / rate);  // n = -1
  for (std::size_t n = 0; n < length && at + n < out.size(); ++n) {
    out[at + n] += static_cast<float>(scale * c1);
    c2 = a1 * c1 + a2 * y_prev;
    y_prev = c1;
    c1 = c2;
  }
}

// The arm's motors and gears: broadband noise (a band around kMotorHz) whose amplitude follows the
// joints' speed, rising over kMotorAttack and dying away over kMotorRelease after the arm stops.
void add_motor_noise(const ContactTrace& trace, int rate, double gain, NoiseSource& noise,
                     std::vector<float>& out) {
  if (gain <= 0 || trace.steps == 0 || trace.joint_speed.empty()) return;
  // RBJ band-pass biquad (constant 0 dB peak gain).
  const double w0 = kTwoPi * kMotorHz / rate;
  const double bandwidth = std::sin(w0) / (2.0 * kMotorQ);
  const double a0 = 1 + bandwidth;
  const double b0 = bandwidth / a0, b2 = -bandwidth / a0, a1 = -2 * std::cos(w0) / a0,
               a2 = (1 - bandwidth) / a0;
  const double attack = 1.0 - std::exp(-1.0 / (kMotorAttack * rate));
  const double release = 1.0 - std::exp(-1.0 / (kMotorRelease * rate));
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

// The room's noise at `rms`, flat below `corner_hz` and falling 6 dB per octave above it (white
// through a one-pole low-pass). A real room's noise is dominated by low frequencies (ventilation,
// traffic, the building: ANSI/ASA S12.2's room-criterion curves fall 5 dB per octave band from
// 16 Hz), and the lab's templates carried far more 100-500 Hz than white noise does; what it does
// to the realism targets is in docs/simulator.md (session 6). Both capsules hear it alike: it is
// the room's, and they are 10 cm apart in it.
std::vector<float> room_noise(std::size_t frames, int rate, double corner_hz, double rms,
                              NoiseSource& noise) {
  std::vector<float> out(frames);
  const double a = 1.0 - std::exp(-kTwoPi * corner_hz / rate);
  // A one-pole low-pass y += a (x - y) passes a / (2 - a) of unit white noise's power.
  const double gain = rms * std::sqrt((2.0 - a) / a);
  // Started in its steady state (a draw of the filtered process) rather than at zero, so the first
  // samples are as loud as the rest.
  double y = std::sqrt(a / (2.0 - a)) * noise.next();
  for (float& x : out) {
    y += a * (noise.next() - y);
    x = static_cast<float>(gain * y);
  }
  return out;
}

// The recorder's peak limiter (stereo-linked): looks kLimiterLookahead ahead, lowers the gain at
// once so no sample exceeds the ceiling, holds it, then lets it recover. It is why the lab's four
// strikes peak within 0.3 dB of each other at -3 dBFS whatever the object.
void apply_limiter(const RecordingConfig& rec, int rate,
                   std::array<std::vector<float>, 2>& channels) {
  const std::size_t frames = channels[0].size();
  const double ceiling = std::pow(10.0, rec.limiter_ceiling_dbfs / 20.0);
  const auto ahead = static_cast<std::size_t>(kLimiterLookahead * rate);
  const auto hold = static_cast<std::size_t>(rec.limiter_hold_s * rate);
  const double recover = 1.0 - std::exp(-1.0 / (rec.limiter_release_s * rate));
  std::vector<float> peak(frames);
  for (std::size_t i = 0; i < frames; ++i)
    peak[i] = std::max(std::abs(channels[0][i]), std::abs(channels[1][i]));
  // The gain a sample needs is ceiling / (the largest peak over [i, i + ahead]) when that peak is
  // above the ceiling, else 1. Few samples are above it (a strike's first milliseconds), so only
  // the windows that hold one are scanned, and a stretch where nothing is needed and the gain is
  // exactly 1 is skipped whole.
  std::vector<std::size_t> over;
  for (std::size_t i = 0; i < frames; ++i)
    if (peak[i] > ceiling) over.push_back(i);
  std::size_t next_over = 0;  // the first entry of `over` at or after i
  double gain = 1.0;
  std::size_t held_until = 0;
  for (std::size_t i = 0; i < frames; ++i) {
    while (next_over < over.size() && over[next_over] < i) ++next_over;
    const bool limit = next_over < over.size() && over[next_over] <= i + ahead;
    if (!limit && gain == 1.0) {
      // Nothing to do until the window reaches the next sample above the ceiling.
      if (next_over == over.size()) break;
      i = over[next_over] - ahead - 1;  // the loop's ++i lands on the window's first such i
      continue;
    }
    double needed = 1.0;
    if (limit) {
      float window_peak = 0;
      for (std::size_t k = i; k < frames && k <= i + ahead; ++k)
        window_peak = std::max(window_peak, peak[k]);
      needed = ceiling / window_peak;
    }
    if (needed < gain) {
      gain = needed;
      held_until = i + hold;
    } else if (i >= held_until) {
      gain += recover * (needed - gain);
    }
    if (gain != 1.0) {  // x * 1 is x: the untouched stretches are left as they are
      channels[0][i] = static_cast<float>(channels[0][i] * gain);
      channels[1][i] = static_cast<float>(channels[1][i] * gain);
    }
  }
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
      table_impedance_(plate_point_impedance(table.material, table.thickness)),
      object_mode_scale_(kReferenceModalMass / object.total_mass()) {
  std::erase_if(table_modes_, [&](const Mode& m) {
    return m.frequency_hz >= 0.45 * config.recording.sample_rate;
  });
}

double SimulatedRecorder::contact_ring_decay(const Impact& impact) const {
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

  // What varies from recording to recording: where the microphone stand was, how loud the room was.
  const auto& var = config_.variability;
  const double mic_offset = var.microphone_distance.draw(rng);
  const double noise_db = rec.noise_dbfs + var.background_db.draw(rng);

  // Per-mode drives: each impact is an impulse of momentum m_eff v weighted by the pressure its
  // force pulse radiates at the mode's frequency (dipole radiation: omega times the pulse spectrum)
  // and, for ring modes, by the rim contact pattern.
  std::vector<ModeDrive> object_drives(object_modes_.size()), table_drives(table_modes_.size());
  std::vector<float> dry(frames, 0.0f);
  for (const Impact& impact : trace.impacts) {
    const auto at = static_cast<std::size_t>(std::lround(impact.time_s * rate));
    if (at >= frames) continue;
    const double momentum = impact.effective_mass * impact.normal_speed;
    const double tau = contact_time(impact);
    auto radiated = [&](double f) {
      return f / kReferenceHz * hertz_pulse_envelope(kTwoPi * f, tau);
    };
    for (std::size_t k = 0; k < object_modes_.size(); ++k) {
      const Mode& m = object_modes_[k];
      object_drives[k].impulses.emplace_back(
          at, object_mode_scale_ * momentum * m.gain * radiated(m.frequency_hz) *
                  ring_excitation(impact.contacts, m.azimuthal_order));
    }
    for (std::size_t k = 0; k < table_modes_.size(); ++k) {
      const Mode& m = table_modes_[k];
      table_drives[k].impulses.emplace_back(
          at, kTableCoupling * momentum * m.gain * radiated(m.frequency_hz) *
                  plate_radiation(m.frequency_hz, table_coincidence_hz_));
    }
    add_contact_ring(momentum, tau, contact_ring_decay(impact), at, rate, dry);
  }
  NoiseSource noise(rng);
  const std::vector<float> friction =
      friction_excitation(trace, rate, frames, rec.friction_gain, noise);
  // Friction drives every mode continuously. Roughness noise is a velocity source (the surfaces are
  // made to follow each other's asperities, see friction_excitation) between two bodies, so the
  // imposed velocity splits between them like a source across two impedances in series (Cremer &
  // Heckl): the object, a mass on the contact (impedance j omega m), takes Z_t / (Z_t + j omega m)
  // of it and the table top (its point impedance Z_t) the rest, j omega m / (Z_t + j omega m). A
  // light cup follows the asperities alone and leaves the table still; a 0.34 kg mug resists above
  // Z_t / (2 pi m) ~ 1.1 kHz, so its 3.7 kHz shell modes are barely driven and the table moves
  // instead. A velocity source sets the modes' velocity whatever their modal mass: no 1 / mass
  // scale here (unlike an impact's impulse). The object radiates as a compact body (dipole: rising
  // with frequency, like the impacts); the table top as a plate, its pressure following its
  // velocity times the square root of its radiation efficiency (plate_radiation), with no dipole
  // factor.
  auto object_share = [&](double f) {
    const double x = kTwoPi * f * object_.total_mass() / table_impedance_;
    return 1.0 / std::sqrt(1.0 + x * x);
  };
  for (std::size_t k = 0; k < object_modes_.size(); ++k) {
    const Mode& m = object_modes_[k];
    object_drives[k].continuous_gain =
        object_share(m.frequency_hz) * m.gain * m.frequency_hz / kReferenceHz;
  }
  // The wall's dense band: bending waves on a thin wall far below its coincidence frequency (53 kHz
  // for the cup's 0.8 mm polycarbonate) radiate as a plate's do (plate_radiation), not as the
  // compact body's dipole.
  std::vector<ModeDrive> dense_drives(dense_modes_.size());
  for (std::size_t k = 0; k < dense_modes_.size(); ++k) {
    const Mode& m = dense_modes_[k];
    dense_drives[k].continuous_gain = object_share(m.frequency_hz) * m.gain *
                                      plate_radiation(m.frequency_hz, wall_coincidence_hz_);
  }
  for (std::size_t k = 0; k < table_modes_.size(); ++k) {
    const Mode& m = table_modes_[k];
    const double object = object_share(m.frequency_hz);
    table_drives[k].continuous_gain = std::sqrt(1.0 - object * object) * m.gain *
                                      plate_radiation(m.frequency_hz, table_coincidence_hz_);
  }

  std::pair<std::size_t, std::size_t> friction_span{frames, 0};
  for (std::size_t n = 0; n < friction.size(); ++n)
    if (friction[n] != 0.0f) {
      friction_span.first = std::min(friction_span.first, n);
      friction_span.second = n;
    }

  // friction_active[n]: how many of the first n samples have friction (to find silent stretches).
  std::vector<std::size_t> friction_active(friction.size() + 1, 0);
  for (std::size_t n = 0; n < friction.size(); ++n)
    friction_active[n + 1] = friction_active[n] + (friction[n] != 0.0f);
  render_modes(object_modes_, object_drives, friction, friction_span, friction_active, rate, dry);
  render_modes(table_modes_, table_drives, friction, friction_span, friction_active, rate, dry);
  render_modes(dense_modes_, dense_drives, friction, friction_span, friction_active, rate, dry);
  // The rubbing contact itself radiates broadband noise besides ringing the modes.
  for (std::size_t n = 0; n < frames; ++n)
    dry[n] += static_cast<float>(kDirectFriction) * friction[n];
  add_motor_noise(trace, rate, rec.motor_noise_gain, noise, dry);

  // The room: the dry sound plus its reverberant tail, shared by both capsules (they are
  // centimetres apart in the same room).
  const std::vector<float> room = add_room(dry, reverb_taps(config_.room, rate, rng));

  // Two capsules either side of the microphone position along y; each hears the room's sound with
  // its own delay and 1/r gain; the recorder's limiter acts on both alike; then its own noise.
  const auto& mic = config_.microphone;
  std::array<std::vector<float>, 2> heard;
  for (int channel = 0; channel < 2; ++channel) {
    const double offset = (channel == 0 ? 0.5 : -0.5) * mic.capsule_spacing;
    const double dx = mic.position[0] - trace.object_position[0];
    const double dy = mic.position[1] + offset - trace.object_position[1];
    const double dz = mic.position[2] - (trace.object_position[2] + kSourceHeight);
    const double distance = std::max(0.1, std::sqrt(dx * dx + dy * dy + dz * dz) + mic_offset);
    heard[channel].assign(frames, 0.0f);
    add_delayed(room, static_cast<std::size_t>(std::lround(distance / kSpeedOfSound * rate)),
                static_cast<float>(rec.output_gain * kDirectPathGain / distance), heard[channel]);
  }
  apply_limiter(rec, rate, heard);

  const auto lead = static_cast<std::size_t>(std::lround(rec.lead_in_s * rate));
  audio::AudioClip clip;
  clip.sample_rate = rate;
  clip.channels = 2;
  clip.samples.assign((lead + frames) * 2, 0.0f);  // the recorder's opening: exact digital zeros
  // The background: by default white noise of its own in each capsule (the recorder's noise, and
  // the lab's level); with recording.noise_corner_hz > 0 the room's low-frequency noise instead.
  const double noise_rms = std::pow(10.0, noise_db / 20.0);
  const std::vector<float> room_background =
      rec.noise_corner_hz > 0 ? room_noise(frames, rate, rec.noise_corner_hz, noise_rms, noise)
                              : std::vector<float>{};
  const float full_scale_max = 32767.0f / 32768.0f;
  for (int channel = 0; channel < 2; ++channel)
    for (std::size_t i = 0; i < frames; ++i) {
      const float background = room_background.empty()
                                   ? static_cast<float>(noise_rms) * noise.next()
                                   : room_background[i];
      clip.samples[2 * (lead + i) + channel] =
          std::clamp(heard[channel][i] + background, -1.0f, full_scale_max);
    }
  return clip;
}

Recording simulate_recording(SimulatedRobot& robot, const SimulatedRecorder& recorder,
                             SoundAction action, Rng& rng) {
  Recording r;
  robot.reset_trial(rng);
  r.outcome = robot.execute(action, rng);
  r.clip = recorder.record(r.outcome, rng);
  return r;
}

}  // namespace echoplan::sim
