#include "perception/recording_features.h"

#include <algorithm>
#include <filesystem>

#include "perception/summary_features.h"

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
                                       const ProgressFn& progress) {
  FeatureSet features;
  features.root = set.root;
  features.objects = set.objects;
  for (const std::string& action : set.actions)
    features.actions.push_back({action, {}, {Modality{"audio", summary_feature_names(), {}}}});
  ClipAnalyzer analyzer(settings);
  ClipAnalysis analysis;
  for (std::size_t i = 0; i < set.recordings.size(); ++i) {
    const Recording& r = set.recordings[i];
    const int object = set.object_index(r.object);
    ActionData& action = features.actions[static_cast<std::size_t>(
        std::find(set.actions.begin(), set.actions.end(), r.action) - set.actions.begin())];
    action.rows.push_back({object, features.add_session(object, session_of(r, set))});
    analyzer.analyse(read_recording(r.path, settings.sample_rate), r.path, analysis);
    const auto summary = summary_features(analysis);
    action.modalities.front().rows.emplace_back(summary.begin(), summary.end());
    if (progress)
      progress("analyse", static_cast<int>(i + 1), static_cast<int>(set.recordings.size()));
  }
  return features;
}

}  // namespace echoplan::perception
