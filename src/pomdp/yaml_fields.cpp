#include "pomdp/yaml_fields.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "common/error.h"

namespace echoplan::pomdp {

int YamlFields::line_of(const YAML::Node& node) {
  if (!node.IsDefined()) return 0;
  return std::max(0, node.Mark().line + 1);
}

void YamlFields::fail(const YAML::Node& node, const std::string& problem) const {
  throw InputError(file_, line_of(node), problem);
}

void YamlFields::expect_map(const YAML::Node& node, const std::string& what) const {
  if (!node.IsMap()) fail(node, what + " must be a mapping of key: value lines");
}

YAML::Node YamlFields::optional(const YAML::Node& map, const std::string& key,
                                const std::string& what) const {
  expect_map(map, what);
  return map[key];
}

YAML::Node YamlFields::require(const YAML::Node& map, const std::string& key,
                               const std::string& what) const {
  YAML::Node value = optional(map, key, what);
  if (!value.IsDefined()) fail(map, "missing key '" + key + "' in " + what);
  return value;
}

void YamlFields::only_keys(const YAML::Node& map, std::initializer_list<const char*> allowed,
                           const std::string& what) const {
  expect_map(map, what);
  const std::set<std::string> ok(allowed.begin(), allowed.end());
  for (auto it = map.begin(); it != map.end(); ++it) {
    const std::string key = it->first.IsScalar() ? it->first.Scalar() : std::string("?");
    if (!ok.count(key)) {
      std::string list;
      for (const char* k : allowed) list += std::string(list.empty() ? "" : ", ") + k;
      fail(it->first, "unknown key '" + key + "' in " + what + " (expected one of: " + list + ")");
    }
  }
}

double YamlFields::number(const YAML::Node& node, const std::string& what) const {
  if (!node.IsScalar()) fail(node, what + " must be a number");
  double value = 0.0;
  if (!YAML::convert<double>::decode(node, value) || !std::isfinite(value)) {
    fail(node, what + " must be a number, got '" + node.Scalar() + "'");
  }
  return value;
}

int YamlFields::non_negative_int(const YAML::Node& node, const std::string& what) const {
  if (!node.IsScalar()) fail(node, what + " must be a whole number");
  long long value = 0;
  if (!YAML::convert<long long>::decode(node, value)) {
    fail(node, what + " must be a whole number, got '" + node.Scalar() + "'");
  }
  if (value < 0) fail(node, what + " must not be negative, got " + std::to_string(value));
  if (value > 1'000'000'000) fail(node, what + " is too large (" + std::to_string(value) + ")");
  return static_cast<int>(value);
}

std::string YamlFields::name(const YAML::Node& node, const std::string& what) const {
  if (!node.IsScalar() || node.Scalar().empty()) fail(node, what + " must be a non-empty name");
  return node.Scalar();
}

std::vector<double> YamlFields::numbers(const YAML::Node& node, const std::string& what) const {
  if (!node.IsSequence()) fail(node, what + " must be a list of numbers like [0.5, 0.5]");
  std::vector<double> out;
  for (const auto& item : node) out.push_back(number(item, "each entry of " + what));
  return out;
}

std::vector<std::string> YamlFields::names(const YAML::Node& node, const std::string& what) const {
  if (!node.IsSequence()) fail(node, what + " must be a list of names like [a, b]");
  std::vector<std::string> out;
  std::set<std::string> seen;
  for (const auto& item : node) {
    out.push_back(name(item, "each entry of " + what));
    if (!seen.insert(out.back()).second)
      fail(item, "duplicate name '" + out.back() + "' in " + what);
  }
  if (out.empty()) fail(node, what + " must not be empty");
  return out;
}

}  // namespace echoplan::pomdp
