#include "sim/sound_microphone.h"

#include <algorithm>
#include <cmath>

#include "sim/modal_model.h"
#include "sim/sound_room.h"

namespace echoplan::sim {

namespace {

// m above the table: where the object radiates from, taken as a point low on its wall (the
// objects are 10-23 cm tall: objects/catalogue.yaml). A geometric choice, not tuned to the lab's
// recordings: it only sets each capsule's distance (delay and 1/r gain).
constexpr double kSourceHeight = 0.02;
// Pressure at 1 m per unit modal amplitude. A scale, not a tuned value of its own: only its product
// with recording.output_gain reaches the clip, and that is the tuned, configurable one.
constexpr double kDirectPathGain = 0.3;

}  // namespace

std::array<std::vector<float>, 2> capsules_hear(const std::vector<float>& room,
                                                const MicrophoneConfig& mic,
                                                const RecordingConfig& rec,
                                                const std::array<double, 3>& object_position,
                                                double mic_offset, int rate) {
  const std::size_t frames = room.size();
  // Two capsules either side of the microphone position along y; each hears the room's sound with
  // its own delay and 1/r gain; the recorder's limiter acts on both alike; then its own noise.
  std::array<std::vector<float>, 2> heard;
  for (int channel = 0; channel < 2; ++channel) {
    const double offset = (channel == 0 ? 0.5 : -0.5) * mic.capsule_spacing;
    const double dx = mic.position[0] - object_position[0];
    const double dy = mic.position[1] + offset - object_position[1];
    const double dz = mic.position[2] - (object_position[2] + kSourceHeight);
    const double distance = std::max(0.1, std::sqrt(dx * dx + dy * dy + dz * dz) + mic_offset);
    heard[channel].assign(frames, 0.0f);
    add_delayed(room, static_cast<std::size_t>(std::lround(distance / kSpeedOfSound * rate)),
                static_cast<float>(rec.output_gain * kDirectPathGain / distance), heard[channel]);
  }
  return heard;
}

void apply_limiter(const RecordingConfig& rec, int rate,
                   std::array<std::vector<float>, 2>& channels) {
  const std::size_t frames = channels[0].size();
  const double ceiling = std::pow(10.0, rec.limiter_ceiling_dbfs / 20.0);
  const auto ahead = static_cast<std::size_t>(rec.limiter_lookahead_s * rate);
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

audio::AudioClip recorder_output(const std::array<std::vector<float>, 2>& heard,
                                 const RecordingConfig& rec, double noise_db, NoiseSource& noise) {
  const int rate = rec.sample_rate;
  const std::size_t frames = heard[0].size();
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

}  // namespace echoplan::sim
