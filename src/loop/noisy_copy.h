// A noisy copy of a recordings tree: every recording mixed with background noise at an
// event-to-background ratio (sim/background_noise.h), written under the same relative path, with a
// manifest that says which source and ratio each got. What `echoplan add-noise` writes, and the
// training set a campaign's arm `trained_in_noise` learns from (multi-condition training: the
// quiet recordings and their noisy twins together).
//
// A recording's noise follows from the seed and its relative path alone, so a rerun (after an
// interruption, or on another machine) writes the same bytes.
#pragma once

#include <atomic>
#include <cstdint>
#include <filesystem>

#include "common/progress.h"
#include "perception/recording_set.h"
#include "robot/noisy_recorder.h"

namespace echoplan::loop {

struct NoisyCopyOptions {
  std::uint64_t seed = 1;
  // Keep the quiet recording beside its noisy twin (`<name>.noisy.<ext>`), both in the twin's
  // session (the recording's own, or the recording alone when it has none), so cross-validation
  // by session never tests a recording against its own twin.
  bool keep_quiet = false;
};

// Writes the copy of `set` into `out` (refused when it is the set's own folder) and
// `out`/manifest.csv (file, object, action, session when the set has sessions or keep_quiet,
// ebr_db, noise: empty and "none" for a quiet recording). A performance's series files
// (<name>.<modality>.csv) are copied as they are beside its noisy (and quiet) audio, and one with
// no audio is copied as it is. `progress("add noise", done, total)`.
// Returns the recordings written; fewer than the set's when `stop` became true (the manifest then
// lists those, so an interrupted copy is a recordings tree too).
std::size_t write_noisy_copy(const perception::RecordingSet& set, const robot::WorldNoise& noise,
                             const std::filesystem::path& out, const NoisyCopyOptions& options,
                             const ProgressFn& progress, const std::atomic<bool>& stop);

}  // namespace echoplan::loop
