// A labelled set of recordings on disk: DIR/<object>/<action>/<file>, optionally with the
// manifest.csv that `echoplan synth-recordings` writes. A performance is an audio file
// <name>.wav (or .flac, .aiff, .aif), the series of other sensors beside it,
// <name>.<modality>.csv (signal/series.h), or both (docs/feature-sets.md, "Raw signals").
//
// Training and evaluation read recordings through this one loader so that every tool sees the same
// objects, actions and files in the same order, and every malformed folder gets the same clear
// error (InputError naming the path and the problem) before any audio is decoded.
#pragma once

#include <string>
#include <vector>

#include "audio/clip.h"

namespace echoplan::perception {

// One sensor's series of a performance: DIR/<object>/<action>/<name>.<modality>.csv.
struct SeriesFile {
  std::string modality;  // from the file name; never "audio"
  std::string path;      // as opened
};

// One recording: where it is and what it is a recording of.
struct Recording {
  // As opened (DIR joined with the relative path): the performance's audio file, or its first
  // series file when it has no audio (a haptic-only robot's).
  std::string path;
  bool audio = true;               // `path` is an audio file
  std::vector<SeriesFile> series;  // sorted by modality; empty for audio alone
  std::string object;              // the class label
  std::string action;              // the sensing action that made the sound
  // The manifest's `session` column (one exploration of one object); empty when the manifest has
  // no such column or there is no manifest, meaning each recording is its own session.
  std::string session;
  // True when the manifest's `noise` column names a source (not empty, not "none"): a copy of a
  // performance mixed with background noise (loop/noisy_copy.h), not a performance of its own.
  bool noisy_copy = false;
  // The manifest's optional `surface` column: the table the performance was made on (a simulated
  // set recorded on several tables names each); empty when not given.
  std::string surface;
};

// Every recording of a folder, grouped by (object, action). Invariants (load_recording_set checks
// them): every object has recordings for every action and at least one recording per (object,
// action).
struct RecordingSet {
  std::string root;                  // the folder it was read from
  std::vector<std::string> objects;  // manifest order if there is a manifest, else sorted by name
  std::vector<std::string> actions;  // same rule
  std::vector<Recording>
      recordings;  // grouped by action, then object, then file name (or manifest order)

  // Recordings of one action, in set order. Empty if the action is not in the set.
  std::vector<const Recording*> of_action(const std::string& action) const;
  // Index of `object` in `objects`, or -1.
  int object_index(const std::string& object) const;
};

// Reads DIR. With DIR/manifest.csv (header with at least the columns file, object and action), the
// set is the manifest's rows, one per performance: each row's file must exist and lie in
// <object>/<action>/, and is the performance's audio file where it has one, else one of its series
// files; a performance on disk that the manifest does not list is an error. Without a manifest,
// every performance under DIR/<object>/<action>/ is a recording. An optional manifest column
// `session` names each recording's session (then required on every row), and an optional column
// `noise` the source a noisy copy was mixed with (Recording::noisy_copy), and `surface` the table
// it was made on. Errors (InputError naming the path, and the manifest line where there is one):
// DIR missing or not a folder; a file where an action folder belongs (files directly in DIR, such
// as a groups file or a README, are ignored); a file that is neither a recording nor a series file
// (hidden files are skipped); two audio files of one name; a series file named `<name>.csv` or
// `<name>.audio.csv`; a manifest row naming a series file of a performance that has audio;
// performances of one action with different signals; an (object, action) folder with no recordings;
// an action recorded for some objects and not others; a manifest row naming a missing file or a
// file outside its folder; an empty session.
RecordingSet load_recording_set(const std::string& dir);

// `set` with each recording's session its table (Recording::surface), so that folds by session hold
// out one table at a time (a table held out like an object); within each (action, object) the
// recordings are ordered by table name, so every object's sessions come in the same order.
// InputError naming the set's folder when a recording has no surface, the set has fewer than two,
// or an object lacks a table on an action that another object was recorded on.
RecordingSet sessions_by_surface(const RecordingSet& set);

// Decodes one recording as the classifiers see it: channels averaged into one, resampled to
// `sample_rate` Hz (any file format, rate, channel count and bit depth libsndfile reads). Throws
// InputError naming the file for anything that is not readable audio.
audio::AudioClip read_recording(const std::string& path, int sample_rate);

}  // namespace echoplan::perception
