#include "common/json_fields.h"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <set>

#include "common/error.h"

namespace echoplan::json_fields {
namespace {

[[noreturn]] void fail(const JsonSource& source, const std::string& path,
                       const std::string& problem) {
  throw InputError(source.file, source.line, path.empty() ? problem : path + ": " + problem);
}

void require_size(const nlohmann::json& value, long long size, const char* what,
                  const std::string& path, const JsonSource& source) {
  if (size >= 0 && static_cast<long long>(value.size()) != size)
    fail(source, path, fmt::format("expected {} {}, found {}", size, what, value.size()));
}

}  // namespace

std::string child(const std::string& path, const std::string& key) {
  return path.empty() ? key : path + "." + key;
}

std::string element(const std::string& path, std::size_t index) {
  return fmt::format("{}[{}]", path, index);
}

const nlohmann::json& member(const nlohmann::json& parent, const std::string& key,
                             const std::string& path, const JsonSource& source) {
  const nlohmann::json* value = optional_member(parent, key, path, source);
  if (value == nullptr) fail(source, child(path, key), "missing");
  return *value;
}

const nlohmann::json* optional_member(const nlohmann::json& parent, const std::string& key,
                                      const std::string& path, const JsonSource& source) {
  if (!parent.is_object()) fail(source, path, "expected an object");
  const auto it = parent.find(key);
  return it == parent.end() ? nullptr : &*it;
}

const nlohmann::json& array(const nlohmann::json& value, const std::string& path,
                            const JsonSource& source) {
  if (!value.is_array()) fail(source, path, "expected an array");
  return value;
}

double number(const nlohmann::json& value, const std::string& path, const JsonSource& source) {
  if (!value.is_number()) fail(source, path, "expected a number");
  const double v = value.get<double>();
  if (!std::isfinite(v)) fail(source, path, "expected a finite number");
  return v;
}

int integer(const nlohmann::json& value, long long min, long long max, const std::string& path,
            const JsonSource& source) {
  if (!value.is_number_integer()) fail(source, path, "expected an integer");
  if (value.is_number_unsigned() &&
      value.get<std::uint64_t>() >
          static_cast<std::uint64_t>(std::numeric_limits<long long>::max()))
    fail(source, path, fmt::format("{} is outside {}..{}", value.get<std::uint64_t>(), min, max));
  const long long v = value.get<long long>();
  if (v < min || v > max) fail(source, path, fmt::format("{} is outside {}..{}", v, min, max));
  return static_cast<int>(v);
}

std::int64_t integer64(const nlohmann::json& value, const std::string& path,
                       const JsonSource& source) {
  if (!value.is_number_integer()) fail(source, path, "expected an integer");
  if (value.is_number_unsigned() &&
      value.get<std::uint64_t>() >
          static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max()))
    fail(source, path, fmt::format("{} is too large", value.get<std::uint64_t>()));
  return value.get<std::int64_t>();
}

std::uint64_t unsigned64(const nlohmann::json& value, const std::string& path,
                         const JsonSource& source) {
  if (!value.is_number_integer()) fail(source, path, "expected an integer");
  if (!value.is_number_unsigned() && value.get<std::int64_t>() < 0)
    fail(source, path, fmt::format("{} is negative", value.get<std::int64_t>()));
  return value.get<std::uint64_t>();
}

bool boolean(const nlohmann::json& value, const std::string& path, const JsonSource& source) {
  if (!value.is_boolean()) fail(source, path, "expected true or false");
  return value.get<bool>();
}

std::string string(const nlohmann::json& value, const std::string& path, const JsonSource& source) {
  if (!value.is_string()) fail(source, path, "expected a string");
  return value.get<std::string>();
}

std::vector<double> numbers(const nlohmann::json& value, long long size, const std::string& path,
                            const JsonSource& source) {
  if (!value.is_array()) fail(source, path, "expected an array of numbers");
  require_size(value, size, "numbers", path, source);
  std::vector<double> out;
  out.reserve(value.size());
  for (std::size_t i = 0; i < value.size(); ++i)
    out.push_back(number(value[i], element(path, i), source));
  return out;
}

std::vector<int> integers(const nlohmann::json& value, long long size, const std::string& path,
                          const JsonSource& source) {
  if (!value.is_array()) fail(source, path, "expected an array of integers");
  require_size(value, size, "integers", path, source);
  std::vector<int> out;
  out.reserve(value.size());
  for (std::size_t i = 0; i < value.size(); ++i)
    out.push_back(integer(value[i], std::numeric_limits<int>::min(),
                          std::numeric_limits<int>::max(), element(path, i), source));
  return out;
}

std::vector<double> matrix(const nlohmann::json& value, long long rows, long long cols,
                           const std::string& path, const JsonSource& source) {
  if (!value.is_array()) fail(source, path, "expected an array of rows");
  require_size(value, rows, "rows", path, source);
  std::vector<double> out;
  for (std::size_t r = 0; r < value.size(); ++r) {
    const auto row = numbers(value[r], cols, element(path, r), source);
    if (cols < 0) cols = static_cast<long long>(row.size());
    out.insert(out.end(), row.begin(), row.end());
  }
  return out;
}

std::vector<std::string> strings(const nlohmann::json& value, const std::string& path,
                                 const JsonSource& source) {
  if (!value.is_array()) fail(source, path, "expected an array of strings");
  std::vector<std::string> out;
  for (std::size_t i = 0; i < value.size(); ++i)
    out.push_back(string(value[i], element(path, i), source));
  return out;
}

std::vector<std::string> names(const nlohmann::json& value, long long size, const std::string& path,
                               const JsonSource& source) {
  if (!value.is_array()) fail(source, path, "expected an array of names");
  require_size(value, size, "names", path, source);
  std::vector<std::string> out;
  std::set<std::string> seen;
  for (std::size_t i = 0; i < value.size(); ++i) {
    const std::string where = element(path, i);
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

}  // namespace echoplan::json_fields
