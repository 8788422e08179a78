// Options shared by the commands that hear recordings through background noise (add-noise, run):
// which sources, at which event-to-background ratio (sim/background_noise.h, docs/noise.md).
#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include <vector>

#include "robot/noisy_recorder.h"

namespace echoplan::cli {

struct NoiseFlags {
  std::vector<std::string> sources;  // empty: no noise
  std::string ebr;                   // "X" or "LO:HI" dB
  int talkers = 1;                   // recorded sources heard at once (babble)
};

// Adds --noise, --ebr and --talkers to `cmd`; `required`: both must be given (add-noise), else both
// or neither.
void add_noise_options(CLI::App& cmd, NoiseFlags& flags, bool required);

// The noise the flags name, its sources read now; none without --noise. InputError for --ebr
// without --noise (or the reverse), a bad ratio or a source that is not there.
std::optional<robot::WorldNoise> world_noise(const NoiseFlags& flags);

}  // namespace echoplan::cli
