#include "perception/recording_features.h"

#include <algorithm>
#include <filesystem>

#include "common/error.h"
#include "common/file_io.h"
#include "perception/clip_extractor.h"

namespace echoplan::perception {

namespace {

// The recording's session name: the manifest's, or (each recording its own session) its path
// relative to the set's folder.
std::string session_of(const Recording& r, const RecordingSet& set) {
  if (!r.session.empty()) return r.session;
  return std::filesystem::path(r.path).lexically_relative(set.root).generic_string();
}

}  // namespace

FeatureSet feature_set_from_recordings(const RecordingSet& set, const AnalysisSettings& settings,
                                       const ProgressFn& progress, std::string_view extractor) {
  const ClipExtractor& rows_of = clip_extractor(extractor);
  FeatureSet features;
  features.root = set.root;
  features.objects = set.objects;
  for (const std::string& action : set.actions)
    features.actions.push_back(
        {action, {}, {Modality{"audio", rows_of.feature_names(), {}, rows_of.name}}});
  ClipAnalyzer analyzer(settings);
  ClipAnalysis analysis;
  for (std::size_t i = 0; i < set.recordings.size(); ++i) {
    const Recording& r = set.recordings[i];
    const int object = set.object_index(r.object);
    ActionData& action = features.actions[static_cast<std::size_t>(
        std::find(set.actions.begin(), set.actions.end(), r.action) - set.actions.begin())];
    analyzer.analyse(read_recording(r.path, settings.sample_rate), r.path, analysis);
    action.rows.push_back(
        {object, features.add_session(object, session_of(r, set)), analysis.ebr_db, r.noisy_copy});
    Modality& audio = action.modalities.front();
    audio.rows.push_back(rows_of.extract(analysis));
    // An extractor whose row length follows the analysis names its features by their place.
    if (audio.feature_names.empty())
      for (std::size_t f = 1; f <= audio.rows.back().size(); ++f)
        audio.feature_names.push_back("f" + std::to_string(f));
    if (progress)
      progress("analyse", static_cast<int>(i + 1), static_cast<int>(set.recordings.size()));
  }
  return features;
}

DataKind data_kind(const std::string& dir) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::exists(dir, ec))
    throw InputError(dir, 0, "data folder does not exist (a feature set or a recordings tree)");
  if (!fs::is_directory(dir, ec))
    throw InputError(dir, 0, "not a folder (expected a feature set or a recordings tree)");
  if (fs::exists(fs::path(dir) / "manifest.csv", ec)) return DataKind::recordings;
  // Two levels of folders (<object>/<action>/) make a recordings tree; a feature set's action
  // folders hold files only.
  for (const fs::path& object : visible_entries(dir))
    if (fs::is_directory(object, ec))
      for (const fs::path& action : visible_entries(object))
        if (fs::is_directory(action, ec)) return DataKind::recordings;
  return DataKind::features;
}

const char* data_kind_name(DataKind kind) {
  return kind == DataKind::recordings ? "recordings tree" : "feature set";
}

FeatureSet load_data(const std::string& dir, const ProgressFn& progress) {
  if (data_kind(dir) == DataKind::features) return load_feature_set(dir);
  return feature_set_from_recordings(load_recording_set(dir), {}, progress);
}

}  // namespace echoplan::perception
