// A configuration section described once, as a list of fields, and the four things done with it:
// read from the user's YAML (every key checked, unknown keys refused with file:line), written to
// and read back from campaign.json, and written into the campaign's identity (files replaced by
// their contents' fingerprints). A field added to the description is read, written and part of the
// identity everywhere at once.
//
// Internal to src/experiment (campaign_config.cpp describes the campaign with it).
#pragma once

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cstdint>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "common/error.h"
#include "common/json_fields.h"
#include "common/yaml_reader.h"
#include "perception/dataset_task.h"

namespace echoplan::experiment::config_fields {

// What a text field holds.
enum class Text {
  word,    // a name, checked against `choices` when given
  label,   // a name of letters, digits, '_' and '-'
  path,    // a path, relative to the campaign file's folder
  file,    // a path that must name an existing file
  folder,  // a path that must name an existing folder
};

// How a field enters the campaign's identity.
enum class Identity {
  value,           // its value
  unless_default,  // its value, left out at the default (keys added later keep older identities)
  file_hash,       // "<key>_sha": the fingerprint of the file's text ("" for no file)
  data_hash,       // "<key>_sha": the fingerprint of the data read from the folder
  none,            // does not decide results
};

// The worlds a field belongs to: every world, the worlds that plan with problem files (model and
// simulated), or the worlds that replay recorded data.
enum class Worlds { any, problem_files, recorded_data };

template <class T>
using Member =
    std::variant<std::string T::*, bool T::*, std::optional<bool> T::*, int T::*, std::int64_t T::*,
                 std::uint64_t T::*, double T::*, std::vector<std::string> T::*,
                 perception::HoldOut T::*, std::map<std::string, double> T::*,
                 std::map<std::string, std::string> T::*>;

template <class T>
struct Field {
  const char* key;
  Member<T> member;
  Identity identity = Identity::value;
  Worlds worlds = Worlds::any;
  Text text = Text::word;  // text fields
  bool required = false;   // the YAML must give it (where its world applies)
  int min = 0;             // whole numbers, and a map's values: the least allowed
  std::vector<std::string> (*choices)() = nullptr;  // words: the allowed ones
  // A map of words' values: each value's canonical form (InputError for a bad one); null: as read.
  std::string (*canonical)(const std::string&) = nullptr;
  const char* elsewhere = "";  // why the key is refused in the worlds it does not belong to
};

// Where a section is read: the campaign file (for messages and relative paths), the section's name
// as the user writes it, and whether the world replays recorded data.
struct Place {
  std::string source;
  std::string section;  // "world", "planner", "an arm", ...
  bool recorded_data = false;
};

// Fingerprints of the files and folders a campaign reads (16 hex digits; "" for an empty path).
struct Fingerprints {
  std::function<std::string(const std::string& path)> file;
  std::function<std::string(const std::string& folder)> data;
};

inline bool applies(Worlds worlds, bool recorded_data) {
  return worlds == Worlds::any || (worlds == Worlds::recorded_data) == recorded_data;
}

// A path from the campaign file, relative to the file's folder unless absolute.
std::string resolve(const std::string& source, const std::string& path);

// Checks a text field's value from the YAML: its shape, choices and existence; fails at `node`.
void check_text(const YamlReader& f, const YAML::Node& node, const char* key, Text text,
                std::vector<std::string> (*choices)(), const std::string& value);

// Reads one field of `into` from the mapping `map` when present: a key of another world is an
// error saying why, a missing required key one naming the mapping's line.
template <class T>
void read_yaml_field(const YamlReader& f, const YAML::Node& map, const Field<T>& field,
                     const Place& at, T& into) {
  const YAML::Node n = f.optional(map, field.key, at.section);
  if (!applies(field.worlds, at.recorded_data)) {
    if (n) f.fail(n, fmt::format("{} is {}", field.key, field.elsewhere));
    return;
  }
  if (!n) {
    if (field.required) f.require(map, field.key, at.section);
    return;
  }
  std::visit(
      [&](auto member) {
        using V = std::remove_reference_t<decltype(into.*member)>;
        V& value = into.*member;
        if constexpr (std::is_same_v<V, std::string>) {
          value = f.name(n, field.key);
          if (field.text == Text::path || field.text == Text::file || field.text == Text::folder)
            value = resolve(at.source, value);
          check_text(f, n, field.key, field.text, field.choices, value);
        } else if constexpr (std::is_same_v<V, bool> || std::is_same_v<V, std::optional<bool>>) {
          value = f.boolean(n, field.key);
        } else if constexpr (std::is_same_v<V, std::uint64_t>) {
          try {
            value = n.as<std::uint64_t>();
          } catch (const YAML::Exception&) {
            f.fail(n, fmt::format("{} must be a non-negative integer", field.key));
          }
        } else if constexpr (std::is_integral_v<V>) {
          const int read = f.non_negative_int(n, field.key);
          if (read < field.min) f.fail(n, fmt::format("{} must be >= {}", field.key, field.min));
          value = static_cast<V>(read);
        } else if constexpr (std::is_same_v<V, double>) {
          value = f.number(n, field.key);
        } else if constexpr (std::is_same_v<V, std::vector<std::string>>) {
          value = f.names(n, field.key);
        } else if constexpr (std::is_same_v<V, perception::HoldOut>) {
          try {
            value = perception::parse_hold_out(f.name(n, field.key));
          } catch (const InputError& e) {
            f.fail(n, e.problem());
          }
        } else if constexpr (std::is_same_v<V, std::map<std::string, std::string>>) {
          f.expect_map(n, field.key);
          value.clear();
          for (const auto& entry : n) {
            const std::string name = f.name(entry.first, field.key);
            value[name] = f.name(entry.second, std::string(field.key) + "." + name);
            if (field.canonical) try {
                value[name] = field.canonical(value[name]);
              } catch (const InputError& e) {
                f.fail(entry.second, std::string(field.key) + "." + name + ": " + e.problem());
              }
          }
        } else {
          f.expect_map(n, field.key);
          value.clear();
          for (const auto& entry : n) {
            const std::string name = f.name(entry.first, field.key);
            value[name] = f.number(entry.second, std::string(field.key) + "." + name,
                                   NumberRange::at_least(field.min));
          }
        }
      },
      field.member);
}

// Reads the fields of `into` present in the mapping `map` (read_yaml_field); a key neither
// described nor in `read_by_caller` is an error listing them. Absent fields keep `into`'s values.
template <class T>
void read_yaml(const YamlReader& f, const YAML::Node& map, const std::vector<Field<T>>& fields,
               const Place& at, T& into, std::vector<std::string> read_by_caller = {}) {
  f.expect_map(map, at.section);
  std::vector<std::string> keys = std::move(read_by_caller);
  for (const Field<T>& field : fields) keys.emplace_back(field.key);
  f.only_keys(map, keys, at.section);
  for (const Field<T>& field : fields) read_yaml_field(f, map, field, at, into);
}

// A field's value as JSON (a hold-out by its name; a yes-or-no the file did not give as null).
template <class V>
nlohmann::json json_value(const V& value) {
  if constexpr (std::is_same_v<V, perception::HoldOut>)
    return perception::hold_out_name(value);
  else if constexpr (std::is_same_v<V, std::optional<bool>>)
    return value ? nlohmann::json(*value) : nlohmann::json(nullptr);
  else
    return value;
}

// The fields of `from` that belong to the world, as JSON.
template <class T>
nlohmann::json write_json(const std::vector<Field<T>>& fields, const T& from, bool recorded_data) {
  nlohmann::json j = nlohmann::json::object();
  for (const Field<T>& field : fields)
    if (applies(field.worlds, recorded_data))
      std::visit([&](auto member) { j[field.key] = json_value(from.*member); }, field.member);
  return j;
}

// Reads what write_json wrote; a field absent from `j` keeps its value in `into` (folders written
// before the field existed). `path` names the section in messages ("world", "arms[0]").
template <class T>
void read_json(const nlohmann::json& j, const std::vector<Field<T>>& fields,
               const std::string& path, const json_fields::JsonSource& source, bool recorded_data,
               T& into) {
  namespace jf = json_fields;
  for (const Field<T>& field : fields) {
    const nlohmann::json* n = jf::optional_member(j, field.key, path, source);
    if (!n || !applies(field.worlds, recorded_data)) continue;
    const std::string where = jf::child(path, field.key);
    std::visit(
        [&](auto member) {
          using V = std::remove_reference_t<decltype(into.*member)>;
          V& value = into.*member;
          if constexpr (std::is_same_v<V, std::string>)
            value = jf::string(*n, where, source);
          else if constexpr (std::is_same_v<V, bool>)
            value = jf::boolean(*n, where, source);
          else if constexpr (std::is_same_v<V, std::optional<bool>>)
            value =
                n->is_null() ? std::nullopt : std::optional<bool>(jf::boolean(*n, where, source));
          else if constexpr (std::is_same_v<V, int>)
            value = jf::integer(*n, field.min, 1 << 30, where, source);
          else if constexpr (std::is_same_v<V, std::int64_t>)
            value = jf::integer64(*n, where, source);
          else if constexpr (std::is_same_v<V, std::uint64_t>)
            value = jf::unsigned64(*n, where, source);
          else if constexpr (std::is_same_v<V, double>)
            value = jf::number(*n, where, source);
          else if constexpr (std::is_same_v<V, std::vector<std::string>>)
            value = jf::strings(*n, where, source);
          else if constexpr (std::is_same_v<V, perception::HoldOut>)
            try {
              value = perception::parse_hold_out(jf::string(*n, where, source));
            } catch (const InputError& e) {
              throw InputError(source.file, source.line, where + ": " + e.problem());
            }
          else if (!n->is_object())
            throw InputError(source.file, source.line, where + " must be an object");
          else if constexpr (std::is_same_v<V, std::map<std::string, std::string>>)
            for (const auto& [name, text] : n->items())
              value[name] = jf::string(text, jf::child(where, name), source);
          else
            for (const auto& [name, number] : n->items())
              value[name] = jf::number(number, jf::child(where, name), source);
        },
        field.member);
  }
}

// The fields of `from` that decide results, as JSON: files and folders by their fingerprints.
template <class T>
nlohmann::json write_identity(const std::vector<Field<T>>& fields, const T& from,
                              bool recorded_data, const Fingerprints& fingerprints) {
  static const T defaults{};
  nlohmann::json j = nlohmann::json::object();
  for (const Field<T>& field : fields) {
    if (!applies(field.worlds, recorded_data) || field.identity == Identity::none) continue;
    std::visit(
        [&](auto member) {
          const auto& value = from.*member;
          using V = std::remove_cvref_t<decltype(value)>;
          if constexpr (std::is_same_v<V, std::string>) {
            const std::string sha = std::string(field.key) + "_sha";
            if (field.identity == Identity::file_hash)
              return void(j[sha] = fingerprints.file(value));
            if (field.identity == Identity::data_hash)
              return void(j[sha] = fingerprints.data(value));
          }
          if (field.identity == Identity::unless_default && value == defaults.*member) return;
          j[field.key] = json_value(value);
        },
        field.member);
  }
  return j;
}

}  // namespace echoplan::experiment::config_fields
