#include "perception/feature_set.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <set>
#include <utility>

#include "common/csv_reader.h"
#include "common/error.h"
#include "common/file_io.h"

namespace echoplan::perception {
namespace fs = std::filesystem;

namespace {

// One modality file as read: its matrix, and each row's (object, session) names and line.
struct ModalityFile {
  std::string path;
  Modality modality;
  std::vector<std::pair<std::string, std::string>> labels;
  std::vector<int> lines;
};

void check_header(const std::vector<std::string>& header, const std::string& file) {
  if (header.size() < 3 || header[0] != "object" || header[1] != "session")
    throw InputError(file, 1,
                     "the header must be object,session followed by at least one feature name");
  std::set<std::string> seen;
  for (std::size_t c = 2; c < header.size(); ++c) {
    if (header[c].empty())
      throw InputError(file, 1, fmt::format("feature name {} (column {}) is empty", c - 1, c + 1));
    if (!seen.insert(header[c]).second)
      throw InputError(file, 1, fmt::format("feature name '{}' appears twice", header[c]));
  }
}

// The finite number `text` spells exactly (no spaces, no leading '+'), or an InputError.
double parse_feature(const std::string& text, const std::string& feature, const CsvReader& csv) {
  double value = 0.0;
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, value);
  if (text.empty() || error != std::errc() || stop != end)
    throw InputError(csv.file(), csv.line(),
                     fmt::format("feature '{}' is '{}', not a number", feature, text));
  if (!std::isfinite(value))
    throw InputError(csv.file(), csv.line(),
                     fmt::format("feature '{}' is '{}': features must be finite", feature, text));
  return value;
}

ModalityFile read_modality(const fs::path& path) {
  ModalityFile m;
  m.path = path.string();
  m.modality.name = path.stem().string();
  CsvReader csv(read_text_file(m.path, "modality file"), m.path);
  std::vector<std::string> header, cells;
  if (!csv.next(header) || csv.line() != 1)
    throw InputError(m.path, 1, "no header: expected object,session,<feature>,...");
  check_header(header, m.path);
  m.modality.feature_names.assign(header.begin() + 2, header.end());
  while (csv.next(cells)) {
    if (cells.size() != header.size())
      throw InputError(m.path, csv.line(),
                       fmt::format("{} cells, but the header has {} columns (a ragged row)",
                                   cells.size(), header.size()));
    if (cells[0].empty()) throw InputError(m.path, csv.line(), "the object is empty");
    if (cells[1].empty()) throw InputError(m.path, csv.line(), "the session is empty");
    std::vector<double> row(header.size() - 2);
    for (std::size_t c = 2; c < header.size(); ++c)
      row[c - 2] = parse_feature(cells[c], header[c], csv);
    m.modality.rows.push_back(std::move(row));
    m.labels.emplace_back(std::move(cells[0]), std::move(cells[1]));
    m.lines.push_back(csv.line());
  }
  if (m.modality.rows.empty())
    throw InputError(m.path, 0, "no rows: a modality needs at least one performance");
  return m;
}

// Siblings must describe the same performances: the same (object, session) on every row.
void check_same_rows(const ModalityFile& first, const ModalityFile& other) {
  const std::size_t n = std::min(first.labels.size(), other.labels.size());
  for (std::size_t i = 0; i < n; ++i)
    if (first.labels[i] != other.labels[i])
      throw InputError(other.path, other.lines[i],
                       fmt::format("row ({}, {}) differs from {}:{}, which has ({}, {}); all "
                                   "modalities of an action list the same rows in the same order",
                                   other.labels[i].first, other.labels[i].second, first.path,
                                   first.lines[i], first.labels[i].first, first.labels[i].second));
  if (first.labels.size() != other.labels.size()) {
    const bool other_longer = other.labels.size() > n;
    const ModalityFile& longer = other_longer ? other : first;
    const ModalityFile& shorter = other_longer ? first : other;
    throw InputError(longer.path, longer.lines[n],
                     fmt::format("row {} has no counterpart in {}, which has {} rows; all "
                                 "modalities of an action list the same rows in the same order",
                                 n + 1, shorter.path, shorter.labels.size()));
  }
}

// Reads one action folder into `set` (its modalities checked against each other).
void add_action(FeatureSet& set, const fs::path& action_dir) {
  std::vector<ModalityFile> files;
  for (const fs::path& entry : visible_entries(action_dir)) {
    if (!fs::is_regular_file(entry) || entry.extension() != ".csv")
      throw InputError(entry.string(), 0,
                       "expected only modality files <modality>.csv in an action folder");
    files.push_back(read_modality(entry));
    check_same_rows(files.front(), files.back());
  }
  if (files.empty())
    throw InputError(action_dir.string(), 0,
                     "no modality files: expected DIR/<action>/<modality>.csv");
  ActionData action;
  action.name = action_dir.filename().string();
  for (const auto& [object, session] : files.front().labels) {
    const int o = set.add_object(object);
    action.rows.push_back({o, set.add_session(o, session)});
  }
  for (ModalityFile& file : files) action.modalities.push_back(std::move(file.modality));
  set.actions.push_back(std::move(action));
}

// Every object needs rows for every action: a classifier per action needs all classes.
void check_every_object_has_every_action(const FeatureSet& set) {
  for (const ActionData& action : set.actions) {
    std::vector<bool> present(set.objects.size(), false);
    for (const RowLabel& row : action.rows) present[static_cast<std::size_t>(row.object)] = true;
    for (std::size_t o = 0; o < present.size(); ++o)
      if (!present[o])
        throw InputError((fs::path(set.root) / action.name).string(), 0,
                         fmt::format("no rows of object '{}', but other actions have it; every "
                                     "object needs rows for every action",
                                     set.objects[o]));
  }
}

}  // namespace

const ActionData* FeatureSet::action(const std::string& name) const {
  for (const ActionData& a : actions)
    if (a.name == name) return &a;
  return nullptr;
}

int FeatureSet::object_index(const std::string& object) const {
  const auto it = std::find(objects.begin(), objects.end(), object);
  return it == objects.end() ? -1 : static_cast<int>(it - objects.begin());
}

int FeatureSet::add_object(const std::string& object) {
  const int index = object_index(object);
  if (index >= 0) return index;
  objects.push_back(object);
  return static_cast<int>(objects.size()) - 1;
}

int FeatureSet::add_session(int object, const std::string& name) {
  for (std::size_t s = 0; s < sessions.size(); ++s)
    if (sessions[s].object == object && sessions[s].name == name) return static_cast<int>(s);
  sessions.push_back({object, name});
  return static_cast<int>(sessions.size()) - 1;
}

FeatureSet load_feature_set(const std::string& dir) {
  std::error_code ec;
  if (!fs::exists(dir, ec)) throw InputError(dir, 0, "feature set folder does not exist");
  if (!fs::is_directory(dir, ec))
    throw InputError(dir, 0, "not a folder; expected DIR/<action>/<modality>.csv");
  FeatureSet set;
  set.root = dir;
  for (const fs::path& entry : visible_entries(dir))
    if (fs::is_directory(entry)) add_action(set, entry);
  if (set.actions.empty())
    throw InputError(dir, 0, "no action folders: expected DIR/<action>/<modality>.csv");
  check_every_object_has_every_action(set);
  return set;
}

const std::string* ObjectGroups::group_of(const std::string& object) const {
  const auto it = std::find(objects.begin(), objects.end(), object);
  return it == objects.end() ? nullptr : &groups[static_cast<std::size_t>(it - objects.begin())];
}

FeatureSet keep_modalities(const FeatureSet& set, const std::vector<std::string>& modalities) {
  std::set<std::string> present;
  for (const ActionData& action : set.actions)
    for (const Modality& m : action.modalities) present.insert(m.name);
  for (const std::string& name : modalities)
    if (!present.contains(name))
      throw InputError(set.root, 0,
                       fmt::format("no action has a modality '{}' (the data has {})", name,
                                   fmt::join(present, ", ")));
  const auto named = [&](const Modality& m) {
    return std::find(modalities.begin(), modalities.end(), m.name) != modalities.end();
  };
  FeatureSet kept = set;
  for (ActionData& action : kept.actions) {
    if (std::none_of(action.modalities.begin(), action.modalities.end(), named))
      throw InputError(set.root, 0,
                       fmt::format("action '{}' has none of the modalities {}", action.name,
                                   fmt::join(modalities, ", ")));
    std::erase_if(action.modalities, [&](const Modality& m) { return !named(m); });
  }
  return kept;
}

ObjectGroups load_groups(const std::string& file) {
  return parse_groups(read_text_file(file, "groups file"), file);
}

ObjectGroups parse_groups(const std::string& text, const std::string& file) {
  CsvReader csv(text, file);
  std::vector<std::string> cells;
  if (!csv.next(cells) || csv.line() != 1 || cells != std::vector<std::string>{"object", "group"})
    throw InputError(file, 1, "the header must be object,group");
  ObjectGroups groups;
  while (csv.next(cells)) {
    if (cells.size() != 2)
      throw InputError(file, csv.line(),
                       fmt::format("{} cells, but the header has 2 columns", cells.size()));
    if (cells[0].empty()) throw InputError(file, csv.line(), "the object is empty");
    if (cells[1].empty()) throw InputError(file, csv.line(), "the group is empty");
    if (groups.group_of(cells[0]))
      throw InputError(
          file, csv.line(),
          fmt::format("object '{}' is listed twice; each object has one group", cells[0]));
    groups.objects.push_back(std::move(cells[0]));
    groups.groups.push_back(std::move(cells[1]));
  }
  return groups;
}

}  // namespace echoplan::perception
