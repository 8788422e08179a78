#include "experiment/analysed_recordings.h"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <nlohmann/json.hpp>

#include "common/file_io.h"
#include "common/stable_hash.h"

namespace echoplan::experiment {

namespace {

namespace fs = std::filesystem;

constexpr const char* kFormat = "echoplan analysed recordings";
// 2: each row with its measured level (RowLabel::ebr_db); 3: and whether it is a noisy copy
// (RowLabel::noisy_copy); 4: series modalities with their features (Modality::series). A kept
// analysis of an earlier version is analysed again.
constexpr int kVersion = 4;

nlohmann::json to_json(const perception::FeatureSet& data) {
  nlohmann::json sessions = nlohmann::json::array(), actions = nlohmann::json::array();
  for (const perception::Session& s : data.sessions) sessions.push_back({s.object, s.name});
  for (const perception::ActionData& action : data.actions) {
    nlohmann::json rows = nlohmann::json::array(), modalities = nlohmann::json::array();
    for (const perception::RowLabel& row : action.rows)
      rows.push_back({row.object, row.session,
                      row.ebr_db ? nlohmann::json(*row.ebr_db) : nlohmann::json(nullptr),
                      row.noisy_copy});
    for (const perception::Modality& m : action.modalities)
      modalities.push_back({{"name", m.name},
                            {"extractor", m.extractor},
                            {"series", m.series},
                            {"feature_names", m.feature_names},
                            {"rows", m.rows}});
    actions.push_back({{"name", action.name}, {"rows", rows}, {"modalities", modalities}});
  }
  return {
      {"root", data.root}, {"objects", data.objects}, {"sessions", sessions}, {"actions", actions}};
}

// The rows' labels and lengths agree with the set (a damaged file must not reach the campaign).
bool consistent(const perception::FeatureSet& data) {
  for (const perception::Session& s : data.sessions)
    if (s.object < 0 || s.object >= static_cast<int>(data.objects.size())) return false;
  for (const perception::ActionData& action : data.actions) {
    for (const perception::RowLabel& row : action.rows)
      if (row.object < 0 || row.object >= static_cast<int>(data.objects.size()) ||
          row.session < 0 || row.session >= static_cast<int>(data.sessions.size()))
        return false;
    for (const perception::Modality& m : action.modalities) {
      if (m.rows.size() != action.rows.size()) return false;
      for (const auto& row : m.rows)
        if (row.size() != m.feature_names.size()) return false;
    }
  }
  return !data.actions.empty();
}

perception::FeatureSet from_json(const nlohmann::json& j) {
  perception::FeatureSet data;
  data.root = j.at("root").get<std::string>();
  data.objects = j.at("objects").get<std::vector<std::string>>();
  for (const auto& s : j.at("sessions"))
    data.sessions.push_back({s.at(0).get<int>(), s.at(1).get<std::string>()});
  for (const auto& a : j.at("actions")) {
    perception::ActionData action;
    action.name = a.at("name").get<std::string>();
    for (const auto& row : a.at("rows"))
      action.rows.push_back(
          {row.at(0).get<int>(), row.at(1).get<int>(),
           row.at(2).is_null() ? std::nullopt : std::optional<double>(row.at(2).get<double>()),
           row.at(3).get<bool>()});
    for (const auto& m : a.at("modalities"))
      action.modalities.push_back(
          {m.at("name").get<std::string>(), m.at("feature_names").get<std::vector<std::string>>(),
           m.at("rows").get<std::vector<std::vector<double>>>(),
           m.at("extractor").get<std::string>(), m.at("series").get<std::string>()});
    data.actions.push_back(std::move(action));
  }
  return data;
}

}  // namespace

std::string recordings_listing(const perception::RecordingSet& set) {
  std::string text;
  // A file's name, size and time of writing: a changed file gives another listing.
  const auto file_text = [&](const std::string& path) {
    std::error_code error;
    const auto size = fs::file_size(path, error);
    const auto written = fs::last_write_time(path, error).time_since_epoch().count();
    return fmt::format("{}\n{} {}\n", fs::path(path).lexically_relative(set.root).generic_string(),
                       error ? 0 : size, error ? 0 : written);
  };
  for (const perception::Recording& r : set.recordings) {
    text += fmt::format("{}{}\n{}\n{}\n{}\n", file_text(r.path), r.object, r.action, r.session,
                        r.noisy_copy);
    for (const perception::SeriesFile& s : r.series) text += s.modality + '\n' + file_text(s.path);
  }
  return fmt::format("{:016x}", stable_hash(text));
}

std::optional<perception::FeatureSet> read_analysed_recordings(const fs::path& file,
                                                               const std::string& folder,
                                                               const std::string& listing) {
  std::error_code error;
  if (!fs::exists(file, error)) return std::nullopt;
  try {
    const nlohmann::json j = nlohmann::json::parse(read_text_file(file.string(), "analysed audio"));
    if (j.at("format") != kFormat || j.at("version") != kVersion || j.at("folder") != folder ||
        j.at("listing") != listing)
      return std::nullopt;  // another tree, or this one changed since
    perception::FeatureSet data = from_json(j.at("data"));
    if (consistent(data)) return data;
  } catch (const std::exception&) {
  }
  spdlog::warn("{}: damaged; analysing the recordings of {} again", file.string(), folder);
  return std::nullopt;
}

void write_analysed_recordings(const fs::path& file, const std::string& folder,
                               const std::string& listing, const perception::FeatureSet& data) {
  const nlohmann::json j = {{"format", kFormat},
                            {"version", kVersion},
                            {"folder", folder},
                            {"listing", listing},
                            {"data", to_json(data)}};
  write_file_atomically(file, j.dump() + "\n");
}

}  // namespace echoplan::experiment
