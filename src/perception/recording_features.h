// A recordings tree as a feature set: the same kind of data as DIR/<action>/<modality>.csv, with
// the audio's features computed by echoplan's own pipeline (docs/feature-sets.md).
#pragma once

#include <map>
#include <string>
#include <string_view>

#include "common/progress.h"
#include "perception/clip_analysis.h"
#include "perception/feature_set.h"
#include "perception/recording_set.h"

namespace echoplan::perception {

// The series features (signal/series_features.h) chosen per modality of a recordings tree's series,
// by modality name; a modality not named gets signal::kDefaultSeriesFeatures.
using SeriesChoices = std::map<std::string, std::string>;

// The feature set of `set`: its objects and actions in set order, per action one row per
// performance in set order, and one modality per signal (sorted by name). Audio: each clip
// analysed with `settings` and turned into a row by the clip extractor `extractor`
// (clip_extractor.h; "summary", the default classifier's, by default), whose name the modality
// keeps, so a model fitted on it classifies live clips the same way. A series modality: each
// series file's row by the series features `series` chooses for it, whose spec the modality keeps
// (Modality::series). Feature names are the extractor's (f1, f2, ... where it has none). A
// recording's session is its manifest `session`; when that is empty (no session column, or no
// manifest) each recording is its own session, named by its path relative to the set's folder.
// Throws InputError naming a recording that is not readable audio or a bad series file, a series
// whose channels differ from the action's first, a choice for a modality the set has no series of
// or a bad spec, or listing the extractors for an unknown one. `progress` (optional) hears
// ("analyse", done, total) per recording.
FeatureSet feature_set_from_recordings(const RecordingSet& set,
                                       const AnalysisSettings& settings = {},
                                       const ProgressFn& progress = {},
                                       std::string_view extractor = "summary",
                                       const SeriesChoices& series = {});

// What a data folder holds: a recordings tree (DIR/manifest.csv, or folders two levels down,
// DIR/<object>/<action>/) or a feature set (anything else; load_feature_set says what is wrong
// with it). The one test every command and campaign uses. InputError when DIR is missing or not
// a folder.
enum class DataKind { recordings, features };
DataKind data_kind(const std::string& dir);
const char* data_kind_name(DataKind kind);  // "recordings tree" or "feature set"

// DIR as a feature set, whichever kind it is: read, or a recordings tree's audio analysed with
// default settings and its series turned into rows as `series` chooses (`progress` hears
// "analyse"). InputError for a choice of series features on a feature set (its rows are given).
FeatureSet load_data(const std::string& dir, const ProgressFn& progress = {},
                     const SeriesChoices& series = {});

}  // namespace echoplan::perception
