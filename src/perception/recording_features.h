// A recordings tree as a feature set: the same kind of data as DIR/<action>/<modality>.csv, with
// the audio's features computed by echoplan's own pipeline (docs/feature-sets.md).
#pragma once

#include <string>
#include <string_view>

#include "common/progress.h"
#include "perception/clip_analysis.h"
#include "perception/feature_set.h"
#include "perception/recording_set.h"

namespace echoplan::perception {

// The feature set of `set`: its objects and actions in set order, one modality "audio" per action
// whose rows are the action's recordings in set order, each clip analysed with `settings` and
// turned into a row by the clip extractor `extractor` (clip_extractor.h; "summary", the default
// classifier's, by default), whose name the modality keeps, so a model fitted on it classifies live
// clips the same way. Feature names are the extractor's (f1, f2, ... where it has none). A
// recording's session is its manifest `session`; when that is empty (no session column, or no
// manifest) each recording is its own session, named by its path relative to the set's folder.
// Throws InputError naming a recording that is not readable audio, or listing the extractors for an
// unknown one. `progress` (optional) hears ("analyse", done, total) per recording.
FeatureSet feature_set_from_recordings(const RecordingSet& set,
                                       const AnalysisSettings& settings = {},
                                       const ProgressFn& progress = {},
                                       std::string_view extractor = "summary");

// What a data folder holds: a recordings tree (DIR/manifest.csv, or folders two levels down,
// DIR/<object>/<action>/) or a feature set (anything else; load_feature_set says what is wrong
// with it). The one test every command and campaign uses. InputError when DIR is missing or not
// a folder.
enum class DataKind { recordings, features };
DataKind data_kind(const std::string& dir);
const char* data_kind_name(DataKind kind);  // "recordings tree" or "feature set"

// DIR as a feature set, whichever kind it is: read, or a recordings tree's audio analysed with
// default settings (`progress` hears "analyse").
FeatureSet load_data(const std::string& dir, const ProgressFn& progress = {});

}  // namespace echoplan::perception
