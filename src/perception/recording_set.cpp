#include "perception/recording_set.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <set>
#include <tuple>

#include "audio/io.h"
#include "common/csv_reader.h"
#include "common/error.h"
#include "common/file_io.h"

namespace echoplan::perception {
namespace fs = std::filesystem;

namespace {

// Files of DIR/<object>/<action>/ as found on disk: (object, action) -> each performance's file
// (its audio file, else its first series file), relative paths, sorted.
using Layout = std::map<std::pair<std::string, std::string>, std::vector<std::string>>;

// A performance's signals as found on disk, by its file (relative path).
struct Signals {
  bool audio = false;
  std::vector<SeriesFile> series;  // relative paths, sorted by modality
};
using Performances = std::map<std::string, Signals>;

constexpr std::string_view kSeriesSuffix = ".csv";

// Adds one file of an action folder to the performances of that folder (by name).
void add_file(const fs::path& file, const fs::path& root, std::map<std::string, Signals>& by_name,
              std::map<std::string, std::string>& audio_of) {
  const std::string filename = file.filename().string();
  const std::string relative = fs::relative(file, root).generic_string();
  if (audio::is_audio_file(file.string())) {
    const std::string name = file.stem().string();
    if (!audio_of.emplace(name, relative).second)
      throw InputError(file.string(), 0,
                       fmt::format("a second audio file named '{}' (beside {}): a performance has "
                                   "one recording",
                                   name, audio_of.at(name)));
    by_name[name].audio = true;
    return;
  }
  if (!filename.ends_with(kSeriesSuffix))
    throw InputError(file.string(), 0,
                     "not a recording: expected a .wav, .flac, .aiff or .aif file, or a sensor's "
                     "series <name>.<modality>.csv");
  const std::string stem = filename.substr(0, filename.size() - kSeriesSuffix.size());
  const auto dot = stem.rfind('.');
  if (dot == std::string::npos || dot == 0 || dot + 1 == stem.size())
    throw InputError(file.string(), 0,
                     "a series file is named <name>.<modality>.csv (the performance, then the "
                     "sensor: take1.effort.csv)");
  const std::string modality = stem.substr(dot + 1);
  if (modality == "audio")
    throw InputError(file.string(), 0,
                     "'audio' is the modality of a performance's audio file; name the series "
                     "after its sensor");
  by_name[stem.substr(0, dot)].series.push_back({modality, relative});
}

// The performances of one action folder into `layout` and `performances`.
void scan_action(const fs::path& action_dir, const fs::path& root, std::vector<std::string>& files,
                 Performances& performances) {
  std::map<std::string, Signals> by_name;
  std::map<std::string, std::string> audio_of;  // name -> its audio file
  for (const fs::path& file : visible_entries(action_dir)) {
    if (fs::is_directory(file))
      throw InputError(file.string(), 0, "unexpected folder inside an action folder");
    add_file(file, root, by_name, audio_of);
  }
  for (auto& [name, signals] : by_name) {
    std::sort(signals.series.begin(), signals.series.end(),
              [](const SeriesFile& a, const SeriesFile& b) { return a.modality < b.modality; });
    const std::string file = signals.audio ? audio_of.at(name) : signals.series.front().path;
    files.push_back(file);
    performances.emplace(file, std::move(signals));
  }
  std::sort(files.begin(), files.end());
}

Layout scan_folders(const fs::path& root, Performances& performances) {
  Layout layout;
  for (const fs::path& object_dir : visible_entries(root)) {
    // Files beside the object folders (manifest.csv, a groups file, a README) are not recordings.
    if (!fs::is_directory(object_dir)) continue;
    const std::string object = object_dir.filename().string();
    for (const fs::path& action_dir : visible_entries(object_dir)) {
      if (!fs::is_directory(action_dir))
        throw InputError(
            action_dir.string(), 0,
            "expected a folder per action (DIR/<object>/<action>/<recording>), found a file");
      const std::string action = action_dir.filename().string();
      auto& files = layout[{object, action}];
      scan_action(action_dir, root, files, performances);
      if (files.empty())
        throw InputError(action_dir.string(), 0, "no recordings in this (object, action) folder");
    }
  }
  return layout;
}

// The manifest's `file` as the performance it lists: its audio file, or (no audio) any of its
// series. InputError at `line` for a series file of a performance that has audio.
std::string performance_of(const std::string& file, const Performances& performances,
                           const std::string& manifest, int line) {
  if (performances.contains(file)) return file;
  for (const auto& [listed, signals] : performances)
    for (const SeriesFile& s : signals.series)
      if (s.path == file) {
        if (signals.audio)
          throw InputError(manifest, line,
                           fmt::format("file '{}' is a series of the performance recorded in "
                                       "'{}': list the audio file",
                                       file, listed));
        return listed;
      }
  return file;
}

// What a performance's signals are, in words, for messages.
std::string signals_text(const Signals& s) {
  std::vector<std::string> names;
  if (s.audio) names.emplace_back("audio");
  for (const SeriesFile& f : s.series) names.push_back(f.modality);
  return fmt::format("{}", fmt::join(names, ", "));
}

// Every performance of an action has the same signals, so every row of its feature set has every
// modality.
void check_same_signals(const RecordingSet& set) {
  for (const std::string& action : set.actions) {
    const Recording* first = nullptr;
    for (const Recording& r : set.recordings) {
      if (r.action != action) continue;
      if (first == nullptr) {
        first = &r;
        continue;
      }
      const auto modalities = [](const Recording& x) {
        std::vector<std::string> names;
        for (const SeriesFile& f : x.series) names.push_back(f.modality);
        return std::pair(x.audio, names);
      };
      if (modalities(r) != modalities(*first))
        throw InputError(r.path, 0,
                         fmt::format("this performance has {} where {} has {}: every performance "
                                     "of an action needs the same signals",
                                     signals_text({r.audio, r.series}), first->path,
                                     signals_text({first->audio, first->series})));
    }
  }
}

void add_unique(std::vector<std::string>& list, const std::string& name) {
  if (std::find(list.begin(), list.end(), name) == list.end()) list.push_back(name);
}

// What a manifest row says of its file beyond where it is.
struct ManifestEntry {
  std::string session;  // "" when the manifest has no session column
  bool noisy_copy = false;
  std::string surface;  // "" when the manifest has no surface column
};

// Reads DIR/manifest.csv into `set`'s objects and actions (manifest order) and `entries` (each
// listed file -> its row's session and noise). Returns (object, action) -> files in manifest
// order.
Layout read_manifest(const fs::path& root, const fs::path& manifest_path,
                     const Performances& performances, RecordingSet& set,
                     std::map<std::string, ManifestEntry>& entries) {
  const std::string name = manifest_path.string();
  CsvReader csv(read_text_file(name, "manifest"), name);
  std::vector<std::string> header, cells;
  if (!csv.next(header)) throw InputError(name, 1, "empty manifest: expected a header row");
  auto column = [&](const std::string& wanted) {
    return static_cast<std::size_t>(std::find(header.begin(), header.end(), wanted) -
                                    header.begin());
  };
  for (const char* needed : {"file", "object", "action"})
    if (column(needed) == header.size())
      throw InputError(
          name, csv.line(),
          fmt::format("the header has no '{}' column (need file, object, action)", needed));
  const std::size_t file_col = column("file"), object_col = column("object"),
                    action_col = column("action");
  const std::size_t session_col = column("session");  // header.size(): no session column
  const std::size_t noise_col = column("noise");      // the same
  const std::size_t surface_col = column("surface");  // the same
  Layout chosen;
  while (csv.next(cells)) {
    const int line_no = csv.line();
    if (cells.size() != header.size())
      throw InputError(
          name, line_no,
          fmt::format("{} cells, but the header has {} columns", cells.size(), header.size()));
    const std::string file = performance_of(cells[file_col], performances, name, line_no);
    const std::string& object = cells[object_col];
    const std::string& action = cells[action_col];
    // One folder each, so that the file lies inside DIR: "..", "/" or an empty name would let a
    // row reach any file on the machine (found reading the code behind fuzz/recording_set_fuzz).
    for (const std::string* folder : {&object, &action})
      if (folder->empty() || *folder == "." || *folder == ".." ||
          folder->find('/') != std::string::npos)
        throw InputError(name, line_no,
                         fmt::format("'{}' is not a folder name: an object and an action each name "
                                     "one folder inside the set (not empty, no '/', not . or ..)",
                                     *folder));
    const std::string expected_prefix = object + "/" + action + "/";
    if (!file.starts_with(expected_prefix) ||
        file.find('/', expected_prefix.size()) != std::string::npos)
      throw InputError(name, line_no,
                       fmt::format("file '{}' is not inside its folder {}", file, expected_prefix));
    if (!fs::is_regular_file(root / file))
      throw InputError(name, line_no,
                       fmt::format("file '{}' does not exist", (root / file).string()));
    const bool has_session = session_col < header.size();
    if (has_session && cells[session_col].empty())
      throw InputError(name, line_no,
                       fmt::format("file '{}' has an empty session (the manifest has a session "
                                   "column, so every row needs one)",
                                   file));
    const bool noisy =
        noise_col < header.size() && !cells[noise_col].empty() && cells[noise_col] != "none";
    const std::string surface = surface_col < header.size() ? cells[surface_col] : "";
    if (!entries.emplace(file, ManifestEntry{has_session ? cells[session_col] : "", noisy, surface})
             .second)
      throw InputError(name, line_no,
                       fmt::format("the performance of '{}' is listed twice", cells[file_col]));
    add_unique(set.objects, object);
    add_unique(set.actions, action);
    chosen[{object, action}].push_back(file);
  }
  return chosen;
}

}  // namespace

RecordingSet sessions_by_surface(const RecordingSet& set) {
  std::set<std::string> surfaces;
  for (const Recording& r : set.recordings) {
    if (r.surface.empty())
      throw InputError(set.root, 0,
                       fmt::format("'{}' names no table: holding out a table needs the manifest's "
                                   "'surface' column on every row (what `synth-recordings "
                                   "--surface A,B` writes)",
                                   r.path));
    surfaces.insert(r.surface);
  }
  if (surfaces.size() < 2)
    throw InputError(set.root, 0,
                     fmt::format("every recording is on one table ({}): holding out a table needs "
                                 "recordings on at least two",
                                 set.recordings.empty() ? "none" : *surfaces.begin()));
  RecordingSet out = set;
  const auto rank = [](const std::vector<std::string>& names, const std::string& name) {
    return std::find(names.begin(), names.end(), name) - names.begin();
  };
  std::stable_sort(
      out.recordings.begin(), out.recordings.end(), [&](const Recording& a, const Recording& b) {
        return std::tuple(rank(set.actions, a.action), rank(set.objects, a.object), a.surface) <
               std::tuple(rank(set.actions, b.action), rank(set.objects, b.object), b.surface);
      });
  std::set<std::tuple<std::string, std::string, std::string>> made;  // (action, object, surface)
  for (Recording& r : out.recordings) {
    r.session = r.surface;
    made.emplace(r.action, r.object, r.surface);
  }
  for (const std::string& action : set.actions)
    for (const std::string& object : set.objects)
      for (const std::string& surface : surfaces)
        if (!made.contains({action, object, surface}))
          throw InputError(set.root, 0,
                           fmt::format("no recording of '{}' with action '{}' on table '{}': each "
                                       "table is held out in turn, so every object needs every "
                                       "action on every table",
                                       object, action, surface));
  return out;
}

std::vector<const Recording*> RecordingSet::of_action(const std::string& action) const {
  std::vector<const Recording*> out;
  for (const auto& r : recordings)
    if (r.action == action) out.push_back(&r);
  return out;
}

int RecordingSet::object_index(const std::string& object) const {
  const auto it = std::find(objects.begin(), objects.end(), object);
  return it == objects.end() ? -1 : static_cast<int>(it - objects.begin());
}

RecordingSet load_recording_set(const std::string& dir) {
  const fs::path root(dir);
  std::error_code ec;
  if (!fs::exists(root, ec)) throw InputError(dir, 0, "recording folder does not exist");
  if (!fs::is_directory(root, ec))
    throw InputError(dir, 0, "not a folder; expected DIR/<object>/<action>/<recording>");
  Performances performances;
  const Layout layout = scan_folders(root, performances);
  if (layout.empty())
    throw InputError(dir, 0, "no recordings: expected DIR/<object>/<action>/<recording>");

  RecordingSet set;
  set.root = dir;
  // (object, action) -> files in set order.
  Layout chosen;
  std::map<std::string, ManifestEntry> entries;  // manifest file -> its row's session and noise
  const fs::path manifest_path = root / "manifest.csv";
  if (fs::exists(manifest_path)) {
    chosen = read_manifest(root, manifest_path, performances, set, entries);
    for (const auto& [key, files] : layout)
      for (const auto& file : files)
        if (!entries.contains(file))
          throw InputError(
              (root / file).string(), 0,
              "recording is not listed in manifest.csv (add a row or remove the file)");
  } else {
    chosen = layout;
    for (const auto& [key, files] : layout) {
      add_unique(set.objects, key.first);
      add_unique(set.actions, key.second);
    }
    std::sort(set.objects.begin(), set.objects.end());
    std::sort(set.actions.begin(), set.actions.end());
  }

  // Every object must have every action: a classifier per action needs all classes.
  for (const auto& object : set.objects)
    for (const auto& action : set.actions)
      if (!chosen.contains({object, action}))
        throw InputError(
            (root / object / action).string(), 0,
            fmt::format(
                "no recordings of '{}' with action '{}', but other objects have that action; every "
                "object needs recordings for every action",
                object, action));
  for (const auto& action : set.actions)
    for (const auto& object : set.objects)
      for (const auto& file : chosen.at({object, action})) {
        const auto entry = entries.find(file);
        const ManifestEntry listed = entry == entries.end() ? ManifestEntry{} : entry->second;
        const Signals& signals = performances.at(file);
        std::vector<SeriesFile> series;
        for (const SeriesFile& s : signals.series)
          series.push_back({s.modality, (root / s.path).string()});
        set.recordings.push_back({(root / file).string(), signals.audio, std::move(series), object,
                                  action, listed.session, listed.noisy_copy, listed.surface});
      }
  check_same_signals(set);
  return set;
}

audio::AudioClip read_recording(const std::string& path, int sample_rate) {
  return audio::read_audio(
      path, {.channel_policy = audio::ChannelPolicy::mean, .target_sample_rate = sample_rate});
}

}  // namespace echoplan::perception
