// Typed access to YAML nodes that turns every mistake into an InputError with file and line.
//
// yaml-cpp reports positions through node marks (0-based); these helpers convert them to the
// 1-based lines users see and name the key that was wrong, so the loaders never let a yaml-cpp
// exception (or a crash on a wrongly typed node) reach the user. Internal to the pomdp module.
#pragma once

#include <yaml-cpp/yaml.h>

#include <initializer_list>
#include <string>
#include <vector>

namespace echoplan::pomdp {

class YamlFields {
 public:
  explicit YamlFields(std::string file) : file_(std::move(file)) {}

  const std::string& file() const { return file_; }

  // 1-based line of `node`, 0 when yaml-cpp does not know it.
  static int line_of(const YAML::Node& node);

  // Throws InputError(file, line of `node`, problem).
  [[noreturn]] void fail(const YAML::Node& node, const std::string& problem) const;

  // `node` must be a mapping; `what` names it in messages.
  void expect_map(const YAML::Node& node, const std::string& what) const;
  // The value under `key` of mapping `map`; throws "missing key" pointing at the mapping.
  YAML::Node require(const YAML::Node& map, const std::string& key, const std::string& what) const;
  // The value under `key`, or an undefined node when absent.
  YAML::Node optional(const YAML::Node& map, const std::string& key, const std::string& what) const;
  // Rejects keys of `map` not in `allowed` (catches typos such as "discont").
  void only_keys(const YAML::Node& map, std::initializer_list<const char*> allowed,
                 const std::string& what) const;

  double number(const YAML::Node& node, const std::string& what) const;
  int non_negative_int(const YAML::Node& node, const std::string& what) const;
  std::string name(const YAML::Node& node, const std::string& what) const;
  std::vector<double> numbers(const YAML::Node& node, const std::string& what) const;
  std::vector<std::string> names(const YAML::Node& node, const std::string& what) const;

 private:
  std::string file_;
};

}  // namespace echoplan::pomdp
