// The one way echoplan reads YAML input files (problems, the object catalogue, simulator configs):
// every mistake becomes an InputError naming the file, the 1-based line, the field and the fix.
//
//   const YAML::Node root = load_yaml_file(path, "sim config");
//   const YamlReader r(path);
//   r.only_keys(root, {"name", "discount"}, "the problem");               // typos are errors
//   const double discount = r.number(r.require(root, "discount", "the problem"), "discount",
//                                    NumberRange::open(0.0, 1.0));
//
//   const YamlMapping mug(r, "objects.coffee_mug", root["objects"]["coffee_mug"]);  // many fields
//   const double radius = mug.number("radius", NumberRange::above(0));   //
//   "objects.coffee_mug.radius"
//
// `what` arguments name the field as the user wrote it ("planner.depth", "objects.coffee_mug"); the
// message then says what was expected ("must be a number like 0.5"). Loaders wrap their reading in
// read_yaml_guarded() so no yaml-cpp exception (a node shape nobody anticipated) reaches the user.
//
// Needs yaml-cpp's headers: modules that read YAML link yaml-cpp PRIVATE, so their own public
// headers (and consumers of the installed libraries) never see it.
#pragma once

#include <yaml-cpp/yaml.h>

#include <initializer_list>
#include <limits>
#include <string>
#include <vector>

namespace echoplan {

// The most nodes a YAML input may stand for with its aliases expanded: a file from someone else
// cannot make a reader walk a billion nodes from a few lines of anchors and aliases ("billion
// laughs"). yaml-cpp itself refuses nesting deeper than its depth guard (DeepRecursion).
inline constexpr long long kMaxYamlExpandedNodes = 2'000'000;

// Parses YAML `text` read from `source`; a syntax error throws InputError(source, line, "not valid
// YAML: ..."), and so do a text standing for more than kMaxYamlExpandedNodes nodes, a second
// document ("---" after the first) and an alias inside the node its anchor names (a cycle). An
// empty text gives a null node.
YAML::Node parse_yaml(const std::string& text, const std::string& source);

// read_text_file + parse_yaml.
YAML::Node load_yaml_file(const std::string& path, const std::string& what);

// Bounds for YamlReader::number(). Default: any finite number.
struct NumberRange {
  double low = -std::numeric_limits<double>::infinity();
  double high = std::numeric_limits<double>::infinity();  // kInfinity, declared below
  bool low_inclusive = true;
  bool high_inclusive = true;

  static NumberRange closed(double low, double high) { return {low, high, true, true}; }
  static NumberRange open(double low, double high) { return {low, high, false, false}; }
  static NumberRange at_least(double low) { return {low, kInfinity, true, true}; }
  static NumberRange above(double low) { return {low, kInfinity, false, true}; }
  // The same range with its upper bound `high`, excluded.
  NumberRange below(double upper) const { return {low, upper, low_inclusive, false}; }

  bool contains(double x) const;
  // "in [0, 1]", "> 0", ">= 0 and < 0.5": for error messages.
  std::string describe() const;

  static constexpr double kInfinity = std::numeric_limits<double>::infinity();
};

// Typed, checked access to the nodes of one YAML file.
class YamlReader {
 public:
  explicit YamlReader(std::string file) : file_(std::move(file)) {}

  const std::string& file() const { return file_; }

  // 1-based line of `node`, 0 when yaml-cpp does not know it (an undefined node).
  static int line_of(const YAML::Node& node);

  // Throws InputError(file, line of `node`, problem).
  [[noreturn]] void fail(const YAML::Node& node, const std::string& problem) const;

  // `node` must be a mapping; `what` names it in messages.
  void expect_map(const YAML::Node& node, const std::string& what) const;
  // The value under `key` of mapping `map`; a missing key is an error pointing at the mapping.
  YAML::Node require(const YAML::Node& map, const std::string& key, const std::string& what) const;
  // The value under `key`, or an undefined node when absent (test with IsDefined()).
  YAML::Node optional(const YAML::Node& map, const std::string& key, const std::string& what) const;
  // Rejects keys of `map` not in `allowed`, listing the allowed ones (catches "discont").
  void only_keys(const YAML::Node& map, const std::vector<std::string>& allowed,
                 const std::string& what) const;
  void only_keys(const YAML::Node& map, std::initializer_list<const char*> allowed,
                 const std::string& what) const;
  // YAML lets a key appear twice in one mapping and silently keeps one; in an input file that is
  // always a mistake. Rejects it anywhere under `node`, at the second occurrence.
  void reject_duplicate_keys(const YAML::Node& node) const;

  // A finite number within `range`.
  double number(const YAML::Node& node, const std::string& what,
                const NumberRange& range = {}) const;
  // A whole number in [0, 1e9].
  int non_negative_int(const YAML::Node& node, const std::string& what) const;
  // true or false (YAML's spellings: true/false, yes/no, on/off).
  bool boolean(const YAML::Node& node, const std::string& what) const;
  // A non-empty scalar.
  std::string name(const YAML::Node& node, const std::string& what) const;
  // A list of numbers, each finite.
  std::vector<double> numbers(const YAML::Node& node, const std::string& what) const;
  // A list of exactly `count` finite numbers ("[x, y, z]").
  std::vector<double> numbers(const YAML::Node& node, const std::string& what,
                              std::size_t count) const;
  // A non-empty list of distinct names.
  std::vector<std::string> names(const YAML::Node& node, const std::string& what) const;

 private:
  std::string file_;
};

// One mapping of a file read field by field, for entries with many fields (a catalogue object, a
// config section). Messages name the field as "<entry>.<key>" ("objects.coffee_mug.radius").
class YamlMapping {
 public:
  // `node` must be a mapping (else InputError at its line).
  YamlMapping(const YamlReader& reader, std::string entry, YAML::Node node);

  const std::string& entry() const { return entry_; }
  const YAML::Node& node() const { return node_; }
  const YamlReader& reader() const { return reader_; }
  // InputError "<entry>: <problem>" at `at` (at the mapping when `at` is undefined).
  [[noreturn]] void fail(const YAML::Node& at, const std::string& problem) const {
    reader_.fail(at.IsDefined() ? at : node_, entry_ + ": " + problem);
  }

  bool has(const std::string& key) const;
  // The value under `key`; a missing key is an error at the mapping.
  YAML::Node required(const std::string& key) const;
  // Rejects keys not in `allowed`.
  void only_keys(const std::vector<std::string>& allowed) const;

  double number(const std::string& key, const NumberRange& range = {}) const;
  double number_or(const std::string& key, double fallback, const NumberRange& range = {}) const;
  std::string name(const std::string& key) const;
  bool boolean_or(const std::string& key, bool fallback) const;
  std::vector<double> numbers(const std::string& key, std::size_t count) const;

 private:
  std::string field(const std::string& key) const { return entry_ + "." + key; }

  const YamlReader& reader_;
  std::string entry_;
  YAML::Node node_;
};

// Runs `read()`, turning a yaml-cpp exception it lets through (a node shape the checks did not
// anticipate) into InputError(file, line, "unexpected YAML structure: ...").
template <class Read>
auto read_yaml_guarded(const std::string& file, Read&& read) -> decltype(read());

namespace detail {
[[noreturn]] void rethrow_yaml_exception(const std::string& file, const YAML::Exception& e);
}

template <class Read>
auto read_yaml_guarded(const std::string& file, Read&& read) -> decltype(read()) {
  try {
    return read();
  } catch (const YAML::Exception& e) {
    detail::rethrow_yaml_exception(file, e);
  }
}

}  // namespace echoplan
