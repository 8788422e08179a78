// Feature sets: recorded data from any robot and sensor, as the numbers the observation models
// learn from (format: docs/feature-sets.md).
//
// On disk, DIR/<action>/<modality>.csv: the header `object,session,<feature>,...`, then one row
// per performance of the action on that object in that session (a session is one exploration of
// one object: each behaviour performed once or a few times). All modalities of one action list
// the same (object, session) rows in the same order, so row i of every modality is the same
// performance seen by another sensor. A recordings tree (recording_features.h) is the same kind of
// data, with one modality "audio" computed by echoplan's own pipeline.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace echoplan::perception {

// One sensor's view of an action: a matrix of rows x features.
struct Modality {
  std::string name;                        // the file stem ("audio", "haptic", ...)
  std::vector<std::string> feature_names;  // the header after object,session; distinct
  std::vector<std::vector<double>> rows;   // rows[i].size() == feature_names.size(); finite
  // The clip extractor (clip_extractor.h) that computed the rows from recordings ("summary" for a
  // recordings tree's audio), or empty when a sensor gave them: a model fitted on them then
  // classifies live clips the same way.
  std::string extractor;
  // The series features (signal/series_features.h, canonical spec) that computed the rows from a
  // recordings tree's series files, or empty: a model fitted on them computes a replayed or live
  // series' row the same way.
  std::string series{};
};

// A session: one exploration of one object. Names are per object: (mug, "1") and (cup, "1") are
// two sessions.
struct Session {
  int object = 0;    // index into FeatureSet::objects
  std::string name;  // as in the files
};

// Who row i of every modality of an action is about.
struct RowLabel {
  int object = 0;   // index into FeatureSet::objects
  int session = 0;  // index into FeatureSet::sessions
  // The event-to-background ratio measured from the performance's recording (audio/levels.h), in
  // dB: a recordings tree's rows have it, a feature set's none.
  std::optional<double> ebr_db{};
  // A noisy copy of another row's performance (a recordings tree's Recording::noisy_copy): in its
  // quiet recording's session for the folds, but not a repeat of it (sequences_of_rows()).
  bool noisy_copy = false;
};

// One action's data: the row labels it shares with all its modalities.
struct ActionData {
  std::string name;                  // the folder name
  std::vector<RowLabel> rows;        // one per performance, file order
  std::vector<Modality> modalities;  // sorted by name; each has rows.size() rows
};

// Invariants (load_feature_set checks them): at least one action; every action has at least one
// modality and one row, and rows of every object in `objects`.
struct FeatureSet {
  std::string root;  // where it was read from (for messages)
  std::vector<std::string>
      objects;                    // in order of first appearance (actions in order, rows in order)
  std::vector<Session> sessions;  // same rule
  std::vector<ActionData> actions;  // sorted by folder name (load_feature_set)

  // The action called `name`, or nullptr.
  const ActionData* action(const std::string& name) const;
  // Index of `object` in `objects`, or -1.
  int object_index(const std::string& object) const;
  // Index of `object` in `objects`, appending it first if it is new (for loaders).
  int add_object(const std::string& object);
  // Index of the session `name` of object index `object`, appending it first if it is new.
  int add_session(int object, const std::string& name);
};

// Reads DIR/<action>/<modality>.csv (hidden entries skipped; other files directly in DIR, such as
// a groups file or a README, are ignored). Throws InputError(file, line, problem) for: DIR missing
// or not a folder; no action folders; an action folder holding something other than .csv files,
// or no .csv file; a header that is not `object,session,<feature>...` with at least one feature,
// an empty or duplicate feature name; a row whose cell count differs from the header's (ragged);
// an empty object or session; a feature that is not a finite number (NaN and inf are errors); a
// modality with no rows; a modality whose (object, session) rows differ from its first sibling's
// (naming the first differing line of both files); an object that has rows for some actions and
// not others (naming the action folder).
FeatureSet load_feature_set(const std::string& dir);

// `set` with only the modalities named in `modalities` (every action keeps those it has, in its
// order). InputError naming the set's folder for a name no action has, or an action left with
// none.
FeatureSet keep_modalities(const FeatureSet& set, const std::vector<std::string>& modalities);

// Which group each object belongs to (for grouped cross-validation or reporting), in file order.
struct ObjectGroups {
  std::vector<std::string> objects;  // distinct
  std::vector<std::string> groups;   // groups[i] is the group of objects[i]; not empty

  // The group of `object`, or nullptr when it is not listed.
  const std::string* group_of(const std::string& object) const;
};

// Reads a groups file: header `object,group`, then one row per object. Throws InputError(file,
// line, problem) for a missing file, another header, a ragged row, an empty object or group, or an
// object listed twice.
ObjectGroups load_groups(const std::string& file);
// The same from the file's text; `source` names it in messages.
ObjectGroups parse_groups(const std::string& text, const std::string& source);

}  // namespace echoplan::perception
