#include "perception/recording_features.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <filesystem>
#include <optional>

#include "common/error.h"
#include "common/file_io.h"
#include "perception/clip_extractor.h"
#include "signal/series.h"
#include "signal/series_features.h"

namespace echoplan::perception {

namespace {

// The recording's session name: the manifest's, or (each recording its own session) its path
// relative to the set's folder.
std::string session_of(const Recording& r, const RecordingSet& set) {
  if (!r.session.empty()) return r.session;
  return std::filesystem::path(r.path).lexically_relative(set.root).generic_string();
}

}  // namespace

namespace {

// The series features of each series modality of `set`: the choice made for it, else the default.
std::map<std::string, signal::SeriesFeatures> series_features_of(const RecordingSet& set,
                                                                 const SeriesChoices& choices) {
  std::map<std::string, signal::SeriesFeatures> features;
  for (const Recording& r : set.recordings)
    for (const SeriesFile& s : r.series)
      if (!features.contains(s.modality)) {
        const auto chosen = choices.find(s.modality);
        features.emplace(s.modality, signal::parse_series_features(
                                         chosen == choices.end() ? signal::kDefaultSeriesFeatures
                                                                 : chosen->second));
      }
  for (const auto& [modality, spec] : choices)
    if (!features.contains(modality)) {
      std::vector<std::string> names;
      for (const auto& [name, f] : features) names.push_back(name);
      throw InputError(
          set.root, 0,
          fmt::format("series features chosen for '{}', but no performance has a "
                      "'{}' series (series here: {})",
                      modality, modality,
                      names.empty() ? "none" : fmt::format("{}", fmt::join(names, ", "))));
    }
  return features;
}

// The action's modalities, empty, sorted by name, for the signals of its first performance.
std::vector<Modality> empty_modalities(
    const Recording& first, const ClipExtractor& clips,
    const std::map<std::string, signal::SeriesFeatures>& series) {
  std::vector<Modality> modalities;
  if (first.audio) modalities.push_back({"audio", clips.feature_names(), {}, clips.name});
  for (const SeriesFile& s : first.series)
    modalities.push_back({s.modality, {}, {}, "", series.at(s.modality).spec()});
  std::sort(modalities.begin(), modalities.end(),
            [](const Modality& a, const Modality& b) { return a.name < b.name; });
  return modalities;
}

// Appends one series file's row to `modality`: its feature names come from the action's first
// series, so every later one must have the same channels.
void add_series_row(Modality& modality, const SeriesFile& file,
                    const signal::SeriesFeatures& features) {
  const signal::Series series = signal::read_series_csv(file.path);
  const std::vector<std::string> names = features.feature_names(series.channels);
  if (modality.rows.empty())
    modality.feature_names = names;
  else if (names != modality.feature_names)
    throw InputError(file.path, 1,
                     fmt::format("channels {} differ from the action's first '{}' series ({}): "
                                 "every performance needs the same channels",
                                 fmt::join(series.channels, ","), modality.name,
                                 fmt::join(modality.feature_names, ",")));
  modality.rows.push_back(features.extract(series, file.path));
}

Modality& modality_named(ActionData& action, const std::string& name) {
  return *std::find_if(action.modalities.begin(), action.modalities.end(),
                       [&](const Modality& m) { return m.name == name; });
}

}  // namespace

FeatureSet feature_set_from_recordings(const RecordingSet& set, const AnalysisSettings& settings,
                                       const ProgressFn& progress, std::string_view extractor,
                                       const SeriesChoices& series_choices) {
  const ClipExtractor& rows_of = clip_extractor(extractor);
  const auto series_features = series_features_of(set, series_choices);
  FeatureSet features;
  features.root = set.root;
  features.objects = set.objects;
  for (const std::string& action : set.actions)
    features.actions.push_back(
        {action, {}, empty_modalities(*set.of_action(action).front(), rows_of, series_features)});
  ClipAnalyzer analyzer(settings);
  ClipAnalysis analysis;
  for (std::size_t i = 0; i < set.recordings.size(); ++i) {
    const Recording& r = set.recordings[i];
    const int object = set.object_index(r.object);
    ActionData& action = features.actions[static_cast<std::size_t>(
        std::find(set.actions.begin(), set.actions.end(), r.action) - set.actions.begin())];
    std::optional<double> ebr_db;
    if (r.audio) {
      analyzer.analyse(read_recording(r.path, settings.sample_rate), r.path, analysis);
      ebr_db = analysis.ebr_db;
      Modality& audio = modality_named(action, "audio");
      audio.rows.push_back(rows_of.extract(analysis));
      // An extractor whose row length follows the analysis names its features by their place.
      if (audio.feature_names.empty())
        for (std::size_t f = 1; f <= audio.rows.back().size(); ++f)
          audio.feature_names.push_back("f" + std::to_string(f));
    }
    for (const SeriesFile& s : r.series)
      add_series_row(modality_named(action, s.modality), s, series_features.at(s.modality));
    action.rows.push_back(
        {object, features.add_session(object, session_of(r, set)), ebr_db, r.noisy_copy});
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

FeatureSet load_data(const std::string& dir, const ProgressFn& progress,
                     const SeriesChoices& series) {
  if (data_kind(dir) == DataKind::recordings)
    return feature_set_from_recordings(load_recording_set(dir), {}, progress, "summary", series);
  if (!series.empty())
    throw InputError(dir, 0,
                     fmt::format("series features chosen for '{}', but this is a feature set: its "
                                 "rows are given, not computed from series",
                                 series.begin()->first));
  return load_feature_set(dir);
}

}  // namespace echoplan::perception
