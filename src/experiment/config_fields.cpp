#include "experiment/config_fields.h"

#include <filesystem>

namespace echoplan::experiment::config_fields {

namespace fs = std::filesystem;

std::string resolve(const std::string& source, const std::string& path) {
  if (path.empty() || fs::path(path).is_absolute()) return path;
  return (fs::path(source).parent_path() / path).lexically_normal().string();
}

namespace {

bool is_label(const std::string& name) {
  if (name.empty()) return false;
  for (char c : name)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-')) return false;
  return true;
}

}  // namespace

void check_text(const YamlReader& f, const YAML::Node& node, const char* key, Text text,
                std::vector<std::string> (*choices)(), const std::string& value) {
  std::error_code error;
  switch (text) {
    case Text::word:
      if (choices) {
        const std::vector<std::string> allowed = choices();
        if (std::find(allowed.begin(), allowed.end(), value) == allowed.end())
          f.fail(node,
                 fmt::format("{} '{}' is not one of: {}", key, value, fmt::join(allowed, ", ")));
      }
      return;
    case Text::label:
      if (!is_label(value))
        f.fail(node, fmt::format("{} '{}' may hold only letters, digits, '_' and '-'", key, value));
      return;
    case Text::path:
      return;
    case Text::file:
      if (!fs::is_regular_file(value, error))
        f.fail(node, fmt::format("{} file '{}' does not exist", key, value));
      return;
    case Text::folder:
      if (!fs::is_directory(value, error))
        f.fail(node, fmt::format("{} folder '{}' does not exist", key, value));
      return;
  }
}

}  // namespace echoplan::experiment::config_fields
