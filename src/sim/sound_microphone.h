// The microphone and the recorder: two capsules hearing the room's sound with their own delay and
// 1/r gain, the recorder's peak limiter, its background noise and the 16-bit clip it writes.
#pragma once

#include <array>
#include <vector>

#include "audio/clip.h"
#include "sim/sim_config.h"
#include "sim/sound_noise.h"

namespace echoplan::sim {

// What the two capsules hear of `room` (the room's sound at the object, `frames` samples at `rate`)
// from an object whose base is at `object_position` (m, world), the microphone stand moved by
// `mic_offset` (m) from its configured distance.
std::array<std::vector<float>, 2> capsules_hear(const std::vector<float>& room,
                                                const MicrophoneConfig& mic,
                                                const RecordingConfig& rec,
                                                const std::array<double, 3>& object_position,
                                                double mic_offset, int rate);

// The recorder's peak limiter (stereo-linked): looks rec.limiter_lookahead_s ahead, lowers the gain
// at once so no sample exceeds the ceiling, holds it, then lets it recover. It is why the lab's
// four strikes peak within 0.3 dB of each other at -3 dBFS whatever the object.
void apply_limiter(const RecordingConfig& rec, int rate,
                   std::array<std::vector<float>, 2>& channels);

// The recorder's clip: its lead-in of digital zeros, then `heard` plus the background at
// `noise_db` dBFS (white per capsule, or the room's low-frequency noise:
// recording.noise_corner_hz), clipped to 16-bit full scale.
audio::AudioClip recorder_output(const std::array<std::vector<float>, 2>& heard,
                                 const RecordingConfig& rec, double noise_db, NoiseSource& noise);

}  // namespace echoplan::sim
