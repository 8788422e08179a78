// The room: its sparse reverberant tail (velvet noise) added to the dry sound, and delayed copies.
#pragma once

#include <cstddef>
#include <utility>
#include <vector>

#include "common/rng.h"
#include "sim/sim_config.h"

namespace echoplan::sim {

// The room's response after the direct sound, as sparse taps (delay in samples after the direct
// sound, gain relative to it): taps at random times with random signs under an exponential envelope
// reaching -60 dB at rt60 (velvet noise).
std::vector<std::pair<std::size_t, float>> reverb_taps(const RoomConfig& room, int rate, Rng& rng);

// out[i + delay] += gain * in[i] over the overlap (vectorises).
void add_delayed(const std::vector<float>& in, std::size_t delay, float gain,
                 std::vector<float>& out);

// `room` = `dry` plus every tap's delayed copy, computed a block of output at a time so the block
// stays in cache while all taps are added (taps in the same order for every sample, so the sums are
// exactly those of adding one whole delayed copy after another).
std::vector<float> add_room(const std::vector<float>& dry,
                            const std::vector<std::pair<std::size_t, float>>& taps);

}  // namespace echoplan::sim
