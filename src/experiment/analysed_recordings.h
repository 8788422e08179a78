// A recordings tree's analysed audio, kept in the campaign folder (analysed_recordings.json), so a
// dataset campaign over recordings analyses them once: reopening it to resume, merge its shards or
// rebuild its report reads the rows back instead of opening a recording.
//
// The file is a cache, never an input the user edits: it names the data folder and a fingerprint
// of its listing (every recording's path, object, action and session from the manifest or the
// folders, and each file's size and modification time, read without opening it), and is used only
// when both match. A recording replaced, added or touched makes it stale, and the tree is analysed
// again. A damaged file is ignored the same way (with a warning): nothing is lost but the time.
// The rows read back are bit for bit the ones analysed (JSON numbers round-trip), so results and
// the data's fingerprint in the campaign's identity are the same either way.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "perception/feature_set.h"
#include "perception/recording_set.h"

namespace echoplan::experiment {

inline constexpr const char* kAnalysedRecordings = "analysed_recordings.json";

// 16 hex digits of the tree's listing, as above.
std::string recordings_listing(const perception::RecordingSet& set);

// The kept rows of `folder` from `file`, when it names that folder and listing; none otherwise
// (absent, stale or damaged).
std::optional<perception::FeatureSet> read_analysed_recordings(const std::filesystem::path& file,
                                                               const std::string& folder,
                                                               const std::string& listing);

// Writes `data`, analysed from `folder` with that listing, to `file` (atomically).
void write_analysed_recordings(const std::filesystem::path& file, const std::string& folder,
                               const std::string& listing, const perception::FeatureSet& data);

}  // namespace echoplan::experiment
