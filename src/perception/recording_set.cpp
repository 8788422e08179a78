#include "perception/recording_set.h"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "audio/io.h"
#include "common/error.h"

namespace echoplan::perception {
namespace fs = std::filesystem;

namespace {

bool hidden(const fs::path& p) { return p.filename().string().starts_with("."); }

std::vector<fs::path> sorted_entries(const fs::path& dir) {
  std::vector<fs::path> entries;
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
    if (!hidden(it->path())) entries.push_back(it->path());
  if (ec) throw InputError(dir.string(), 0, "cannot list the folder: " + ec.message());
  std::sort(entries.begin(), entries.end());
  return entries;
}

// Splits one CSV line (no quoting: `echoplan dataset` writes plain names and numbers).
std::vector<std::string> split_csv(const std::string& line) {
  std::vector<std::string> cells;
  std::string cell;
  std::istringstream in(line);
  while (std::getline(in, cell, ',')) cells.push_back(cell);
  if (!line.empty() && line.back() == ',') cells.emplace_back();
  return cells;
}

// Files of DIR/<object>/<action>/ as found on disk: (object, action) -> relative paths, sorted.
using Layout = std::map<std::pair<std::string, std::string>, std::vector<std::string>>;

Layout scan_folders(const fs::path& root) {
  Layout layout;
  for (const fs::path& object_dir : sorted_entries(root)) {
    if (object_dir.filename() == "manifest.csv") continue;
    if (!fs::is_directory(object_dir))
      throw InputError(
          object_dir.string(), 0,
          "expected a folder per object (DIR/<object>/<action>/<recording>), found a file");
    const std::string object = object_dir.filename().string();
    for (const fs::path& action_dir : sorted_entries(object_dir)) {
      if (!fs::is_directory(action_dir))
        throw InputError(
            action_dir.string(), 0,
            "expected a folder per action (DIR/<object>/<action>/<recording>), found a file");
      const std::string action = action_dir.filename().string();
      auto& files = layout[{object, action}];
      for (const fs::path& file : sorted_entries(action_dir)) {
        if (fs::is_directory(file))
          throw InputError(file.string(), 0, "unexpected folder inside an action folder");
        if (!is_recording_file(file.string()))
          throw InputError(file.string(), 0,
                           "not a recording: expected a .wav, .flac, .aiff or .aif file");
        files.push_back(fs::relative(file, root).generic_string());
      }
      if (files.empty())
        throw InputError(action_dir.string(), 0, "no recordings in this (object, action) folder");
    }
  }
  return layout;
}

void add_unique(std::vector<std::string>& list, const std::string& name) {
  if (std::find(list.begin(), list.end(), name) == list.end()) list.push_back(name);
}

}  // namespace

bool is_recording_file(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext == ".wav" || ext == ".flac" || ext == ".aiff" || ext == ".aif";
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
  const Layout layout = scan_folders(root);
  if (layout.empty())
    throw InputError(dir, 0, "no recordings: expected DIR/<object>/<action>/<recording>");

  RecordingSet set;
  set.root = dir;
  // (object, action) -> files in set order.
  Layout chosen;
  const fs::path manifest_path = root / "manifest.csv";
  if (fs::exists(manifest_path)) {
    std::ifstream in(manifest_path);
    if (!in) throw InputError(manifest_path.string(), 0, "cannot open the manifest");
    std::string line;
    if (!std::getline(in, line))
      throw InputError(manifest_path.string(), 1, "empty manifest: expected a header row");
    const auto header = split_csv(line);
    auto column = [&](const std::string& name) {
      const auto it = std::find(header.begin(), header.end(), name);
      if (it == header.end())
        throw InputError(
            manifest_path.string(), 1,
            fmt::format("the header has no '{}' column (need file, object, action)", name));
      return static_cast<std::size_t>(it - header.begin());
    };
    const std::size_t file_col = column("file"), object_col = column("object"),
                      action_col = column("action");
    std::set<std::string> listed;
    for (int line_no = 2; std::getline(in, line); ++line_no) {
      if (!line.empty() && line.back() == '\r') line.pop_back();
      if (line.empty()) continue;
      const auto cells = split_csv(line);
      if (cells.size() != header.size())
        throw InputError(
            manifest_path.string(), line_no,
            fmt::format("{} cells, but the header has {} columns", cells.size(), header.size()));
      const std::string& file = cells[file_col];
      const std::string& object = cells[object_col];
      const std::string& action = cells[action_col];
      const std::string expected_prefix = object + "/" + action + "/";
      if (!file.starts_with(expected_prefix) ||
          file.find('/', expected_prefix.size()) != std::string::npos)
        throw InputError(
            manifest_path.string(), line_no,
            fmt::format("file '{}' is not inside its folder {}", file, expected_prefix));
      if (!fs::is_regular_file(root / file))
        throw InputError(manifest_path.string(), line_no,
                         fmt::format("file '{}' does not exist", (root / file).string()));
      if (!listed.insert(file).second)
        throw InputError(manifest_path.string(), line_no,
                         fmt::format("file '{}' is listed twice", file));
      add_unique(set.objects, object);
      add_unique(set.actions, action);
      chosen[{object, action}].push_back(file);
    }
    for (const auto& [key, files] : layout)
      for (const auto& file : files)
        if (!listed.contains(file))
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
      for (const auto& file : chosen.at({object, action}))
        set.recordings.push_back({(root / file).string(), object, action});
  return set;
}

audio::AudioClip read_recording(const std::string& path, int sample_rate) {
  return audio::read_audio(
      path, {.channel_policy = audio::ChannelPolicy::mean, .target_sample_rate = sample_rate});
}

}  // namespace echoplan::perception
