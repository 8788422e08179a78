#include "perception/json_fields.h"

#include <fmt/format.h>

#include <cmath>
#include <set>

#include "common/error.h"

namespace echoplan::perception::json_fields {
namespace {

[[noreturn]] void fail(const std::string& source, const std::string& path,
                       const std::string& problem) {
  throw InputError(source, 0, path + ": " + problem);
}

}  // namespace

const nlohmann::json& member(const nlohmann::json& parent, const std::string& key,
                             const std::string& path, const std::string& source) {
  if (!parent.is_object()) fail(source, path, "expected an object");
  const auto it = parent.find(key);
  if (it == parent.end()) fail(source, path.empty() ? key : path + "." + key, "missing");
  return *it;
}

double number(const nlohmann::json& value, const std::string& path, const std::string& source) {
  if (!value.is_number()) fail(source, path, "expected a number");
  const double v = value.get<double>();
  if (!std::isfinite(v)) fail(source, path, "expected a finite number");
  return v;
}

int integer(const nlohmann::json& value, long long min, long long max, const std::string& path,
            const std::string& source) {
  if (!value.is_number_integer()) fail(source, path, "expected an integer");
  const long long v = value.get<long long>();
  if (v < min || v > max) fail(source, path, fmt::format("{} is outside {}..{}", v, min, max));
  return static_cast<int>(v);
}

bool boolean(const nlohmann::json& value, const std::string& path, const std::string& source) {
  if (!value.is_boolean()) fail(source, path, "expected true or false");
  return value.get<bool>();
}

std::string string(const nlohmann::json& value, const std::string& path,
                   const std::string& source) {
  if (!value.is_string()) fail(source, path, "expected a string");
  return value.get<std::string>();
}

std::vector<double> numbers(const nlohmann::json& value, long long size, const std::string& path,
                            const std::string& source) {
  if (!value.is_array()) fail(source, path, "expected an array of numbers");
  if (size >= 0 && static_cast<long long>(value.size()) != size)
    fail(source, path, fmt::format("expected {} numbers, found {}", size, value.size()));
  std::vector<double> out;
  out.reserve(value.size());
  for (std::size_t i = 0; i < value.size(); ++i)
    out.push_back(number(value[i], fmt::format("{}[{}]", path, i), source));
  return out;
}

std::vector<double> matrix(const nlohmann::json& value, long long rows, long long cols,
                           const std::string& path, const std::string& source) {
  if (!value.is_array()) fail(source, path, "expected an array of rows");
  if (rows >= 0 && static_cast<long long>(value.size()) != rows)
    fail(source, path, fmt::format("expected {} rows, found {}", rows, value.size()));
  std::vector<double> out;
  for (std::size_t r = 0; r < value.size(); ++r) {
    const auto row = numbers(value[r], cols, fmt::format("{}[{}]", path, r), source);
    if (cols < 0) cols = static_cast<long long>(row.size());
    out.insert(out.end(), row.begin(), row.end());
  }
  return out;
}

std::vector<std::string> names(const nlohmann::json& value, long long size, const std::string& path,
                               const std::string& source) {
  if (!value.is_array()) fail(source, path, "expected an array of names");
  if (size >= 0 && static_cast<long long>(value.size()) != size)
    fail(source, path, fmt::format("expected {} names, found {}", size, value.size()));
  std::vector<std::string> out;
  std::set<std::string> seen;
  for (std::size_t i = 0; i < value.size(); ++i) {
    const std::string where = fmt::format("{}[{}]", path, i);
    std::string name = string(value[i], where, source);
    if (name.empty()) fail(source, where, "empty name");
    if (!seen.insert(name).second) fail(source, where, fmt::format("'{}' appears twice", name));
    out.push_back(std::move(name));
  }
  return out;
}

nlohmann::json rows_of(const std::vector<double>& values, std::size_t rows, std::size_t cols) {
  nlohmann::json out = nlohmann::json::array();
  for (std::size_t r = 0; r < rows; ++r)
    out.push_back(
        std::vector<double>(values.begin() + static_cast<std::ptrdiff_t>(r * cols),
                            values.begin() + static_cast<std::ptrdiff_t>((r + 1) * cols)));
  return out;
}

}  // namespace echoplan::perception::json_fields
