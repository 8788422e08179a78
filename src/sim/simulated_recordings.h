// Simulated recordings: every (object, action) pair simulated and recorded `per_pair` times into
// DIR/<object>/<action>/NNN.wav, with DIR/manifest.csv listing each file, its seed and the trial's
// sampled parameters. Beside (or instead of) the sound, the arm's own sensors
// (sim/arm_sensors.h): NNN.effort.csv (joint torques j1..j7) and NNN.force.csv (the wrist force),
// raw signals of a recordings tree (docs/feature-sets.md).
//
// Each clip has its own seed, derived from the recordings' seed and the clip's object, action and
// index, so `echoplan synth --object O --action A --seed <manifest seed>` reproduces any file bit
// for bit and adding objects does not change the others' recordings. Files appear atomically
// (written under a temporary name, then renamed) and each manifest row is flushed after its file,
// so an interrupted run leaves only finished files, each with its row. The sensors' noise comes
// from a stream of its own (derived from the clip's seed), so asking for them leaves the sound as
// it was.
#pragma once

#include <atomic>
#include <cstdint>
#include <string>
#include <vector>

#include "common/progress.h"
#include "sim/catalogue.h"
#include "sim/sim_config.h"

namespace echoplan::sim {

struct SimulatedRecordingsOptions {
  std::vector<std::string> objects;  // catalogue names; empty = every object in the catalogue
  std::vector<std::string> actions{"slide", "strike"};
  int per_pair = 10;  // recordings per (object, action), >= 1
  std::uint64_t seed = 0;
  std::string output_dir;
  int threads = 2;  // worker threads (>= 1); the files and manifest do not depend on it
  // What each performance records: any of audio, effort, force (at least one, each once).
  std::vector<std::string> signals{"audio"};
};

// The signals a simulated recording can hold, in the order they are written.
const std::vector<std::string>& simulated_signals();

struct SimulatedRecordingsSummary {
  int written = 0;     // clips written (and rows in the manifest)
  int collisions = 0;  // of which the arm touched the table
  bool interrupted = false;
};

// The seed of clip `index` of (object, action) in recordings written with seed `seed`.
std::uint64_t clip_seed(std::uint64_t seed, const std::string& object, const std::string& action,
                        int index);

// Writes the recordings tree. `progress(file, done, total)` is called after each clip. Stops early,
// with summary.interrupted set, when `stop` becomes true (checked between clips). Throws InputError
// for unknown object, action or signal names (before writing anything) and if a file cannot be
// written.
SimulatedRecordingsSummary write_simulated_recordings(const Catalogue& catalogue,
                                                      const SimConfig& config,
                                                      const SimulatedRecordingsOptions& options,
                                                      const ProgressFn& progress,
                                                      const std::atomic<bool>& stop);

}  // namespace echoplan::sim
