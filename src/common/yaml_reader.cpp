#include "common/yaml_reader.h"

#include <yaml-cpp/eventhandler.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <vector>

#include "common/error.h"
#include "common/file_io.h"

namespace echoplan {

namespace {

// Shortest text for a bound in a message: 0.5, 1e+09, 20000.
std::string bound_text(double x) {
  std::ostringstream s;
  s << x;
  return s.str();
}

// Counts the nodes a YAML stream stands for with every alias expanded, from the parser's events
// (aliases are not expanded to count them, so counting is as cheap as parsing), and throws
// YAML::ParserException at the first event past the limit.
class ExpandedNodeCounter final : public YAML::EventHandler {
 public:
  void OnDocumentStart(const YAML::Mark&) override {}
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark& mark, YAML::anchor_t anchor) override { leaf(mark, anchor, 1); }
  void OnAlias(const YAML::Mark& mark, YAML::anchor_t anchor) override {
    // An alias inside the node its anchor names makes yaml-cpp build a cycle, which any walk of
    // the document follows forever (a stack overflow found by fuzz/experiment_files_fuzz).
    for (const Open& o : open_)
      if (o.anchor == anchor)
        throw YAML::ParserException(mark, "an alias inside the node it refers to (a cycle)");
    const auto it = size_.find(anchor);
    leaf(mark, 0, it == size_.end() ? 1 : it->second);
  }
  void OnScalar(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor,
                const std::string&) override {
    leaf(mark, anchor, 1);
  }
  void OnSequenceStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor,
                       YAML::EmitterStyle::value) override {
    open(mark, anchor);
  }
  void OnSequenceEnd() override { close(); }
  void OnMapStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor,
                  YAML::EmitterStyle::value) override {
    open(mark, anchor);
  }
  void OnMapEnd() override { close(); }

 private:
  struct Open {
    YAML::anchor_t anchor;
    long long total_before;
  };
  void leaf(const YAML::Mark& mark, YAML::anchor_t anchor, long long size) {
    total_ += size;
    if (anchor) size_[anchor] = size;
    check(mark);
  }
  void open(const YAML::Mark& mark, YAML::anchor_t anchor) {
    open_.push_back({anchor, total_});
    total_ += 1;
    check(mark);
  }
  void close() {
    const Open o = open_.back();
    open_.pop_back();
    if (o.anchor) size_[o.anchor] = total_ - o.total_before;
  }
  void check(const YAML::Mark& mark) const {
    if (total_ > kMaxYamlExpandedNodes)
      throw YAML::ParserException(mark, "the document stands for more than " +
                                            std::to_string(kMaxYamlExpandedNodes) +
                                            " nodes with its aliases expanded");
  }

  long long total_ = 0;
  std::vector<Open> open_;
  std::map<YAML::anchor_t, long long> size_;
};

}  // namespace

YAML::Node parse_yaml(const std::string& text, const std::string& source) {
  try {
    std::istringstream stream(text);
    YAML::Parser parser(stream);
    ExpandedNodeCounter counter;
    // One document per file (YAML::Load reads the first). Not reading on to the end also matters:
    // yaml-cpp 0.7 never ends some broken streams (a lone ',' yields empty documents forever,
    // found by fuzz/experiment_files_fuzz).
    if (parser.HandleNextDocument(counter) && parser.HandleNextDocument(counter))
      throw YAML::ParserException(YAML::Mark::null_mark(),
                                  "more than one document (echoplan reads one per file)");
    return YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw InputError(source, std::max(0, e.mark.line + 1), "not valid YAML: " + e.msg);
  }
}

YAML::Node load_yaml_file(const std::string& path, const std::string& what) {
  return parse_yaml(read_text_file(path, what), path);
}

bool NumberRange::contains(double x) const {
  const bool above_low = low_inclusive ? x >= low : x > low;
  const bool below_high = high_inclusive ? x <= high : x < high;
  return above_low && below_high;
}

std::string NumberRange::describe() const {
  const bool has_low = std::isfinite(low);
  const bool has_high = std::isfinite(high);
  if (has_low && has_high && low_inclusive == high_inclusive) {
    return std::string("in ") + (low_inclusive ? "[" : "(") + bound_text(low) + ", " +
           bound_text(high) + (high_inclusive ? "]" : ")");
  }
  std::string out;
  if (has_low) out = (low_inclusive ? ">= " : "> ") + bound_text(low);
  if (has_high) {
    out += (out.empty() ? "" : " and ") + std::string(high_inclusive ? "<= " : "< ") +
           bound_text(high);
  }
  return out.empty() ? "finite" : out;
}

int YamlReader::line_of(const YAML::Node& node) {
  if (!node.IsDefined()) return 0;
  return std::max(0, node.Mark().line + 1);
}

void YamlReader::fail(const YAML::Node& node, const std::string& problem) const {
  throw InputError(file_, line_of(node), problem);
}

void YamlReader::expect_map(const YAML::Node& node, const std::string& what) const {
  if (!node.IsMap()) fail(node, what + " must be a mapping of key: value lines");
}

YAML::Node YamlReader::optional(const YAML::Node& map, const std::string& key,
                                const std::string& what) const {
  expect_map(map, what);
  return map[key];
}

YAML::Node YamlReader::require(const YAML::Node& map, const std::string& key,
                               const std::string& what) const {
  YAML::Node value = optional(map, key, what);
  if (!value.IsDefined()) fail(map, "missing key '" + key + "' in " + what);
  return value;
}

void YamlReader::only_keys(const YAML::Node& map, const std::vector<std::string>& allowed,
                           const std::string& what) const {
  expect_map(map, what);
  for (auto it = map.begin(); it != map.end(); ++it) {
    const std::string key = it->first.IsScalar() ? it->first.Scalar() : std::string("?");
    if (std::find(allowed.begin(), allowed.end(), key) == allowed.end()) {
      std::string list;
      for (const auto& k : allowed) list += (list.empty() ? "" : ", ") + k;
      fail(it->first, "unknown key '" + key + "' in " + what + " (expected one of: " + list + ")");
    }
  }
}

void YamlReader::only_keys(const YAML::Node& map, std::initializer_list<const char*> allowed,
                           const std::string& what) const {
  only_keys(map, std::vector<std::string>(allowed.begin(), allowed.end()), what);
}

void YamlReader::reject_duplicate_keys(const YAML::Node& node) const {
  if (node.IsSequence()) {
    for (const auto& item : node) reject_duplicate_keys(item);
    return;
  }
  if (!node.IsMap()) return;
  std::set<std::string> seen;
  for (auto it = node.begin(); it != node.end(); ++it) {
    if (it->first.IsScalar() && !seen.insert(it->first.Scalar()).second) {
      fail(it->first, "key '" + it->first.Scalar() + "' appears twice in the same mapping");
    }
    reject_duplicate_keys(it->second);
  }
}

double YamlReader::number(const YAML::Node& node, const std::string& what,
                          const NumberRange& range) const {
  if (!node.IsScalar()) fail(node, what + " must be a number like 0.5");
  double value = 0.0;
  if (!YAML::convert<double>::decode(node, value) || !std::isfinite(value)) {
    fail(node, what + " must be a number like 0.5, got '" + node.Scalar() + "'");
  }
  if (!range.contains(value)) {
    fail(node, what + " must be " + range.describe() + ", got " + node.Scalar());
  }
  return value;
}

int YamlReader::non_negative_int(const YAML::Node& node, const std::string& what) const {
  if (!node.IsScalar()) fail(node, what + " must be a whole number");
  long long value = 0;
  if (!YAML::convert<long long>::decode(node, value)) {
    fail(node, what + " must be a whole number, got '" + node.Scalar() + "'");
  }
  if (value < 0) fail(node, what + " must not be negative, got " + std::to_string(value));
  if (value > 1'000'000'000) fail(node, what + " is too large (" + std::to_string(value) + ")");
  return static_cast<int>(value);
}

bool YamlReader::boolean(const YAML::Node& node, const std::string& what) const {
  bool value = false;
  if (!node.IsScalar() || !YAML::convert<bool>::decode(node, value)) {
    fail(node, what + " must be true or false");
  }
  return value;
}

std::string YamlReader::name(const YAML::Node& node, const std::string& what) const {
  if (!node.IsScalar() || node.Scalar().empty()) fail(node, what + " must be a non-empty name");
  return node.Scalar();
}

std::vector<double> YamlReader::numbers(const YAML::Node& node, const std::string& what) const {
  if (!node.IsSequence()) fail(node, what + " must be a list of numbers like [0.5, 0.5]");
  std::vector<double> out;
  for (const auto& item : node) out.push_back(number(item, "each entry of " + what));
  return out;
}

std::vector<double> YamlReader::numbers(const YAML::Node& node, const std::string& what,
                                        std::size_t count) const {
  const std::vector<double> out = numbers(node, what);
  if (out.size() != count) {
    fail(node,
         what + " needs " + std::to_string(count) + " numbers, got " + std::to_string(out.size()));
  }
  return out;
}

std::vector<std::string> YamlReader::names(const YAML::Node& node, const std::string& what) const {
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

YamlMapping::YamlMapping(const YamlReader& reader, std::string entry, YAML::Node node)
    : reader_(reader), entry_(std::move(entry)), node_(std::move(node)) {
  reader_.expect_map(node_, entry_);
}

bool YamlMapping::has(const std::string& key) const { return node_[key].IsDefined(); }

YAML::Node YamlMapping::required(const std::string& key) const {
  return reader_.require(node_, key, entry_);
}

void YamlMapping::only_keys(const std::vector<std::string>& allowed) const {
  reader_.only_keys(node_, allowed, entry_);
}

double YamlMapping::number(const std::string& key, const NumberRange& range) const {
  return reader_.number(required(key), field(key), range);
}

double YamlMapping::number_or(const std::string& key, double fallback,
                              const NumberRange& range) const {
  return has(key) ? reader_.number(node_[key], field(key), range) : fallback;
}

std::string YamlMapping::name(const std::string& key) const {
  return reader_.name(required(key), field(key));
}

bool YamlMapping::boolean_or(const std::string& key, bool fallback) const {
  return has(key) ? reader_.boolean(node_[key], field(key)) : fallback;
}

std::vector<double> YamlMapping::numbers(const std::string& key, std::size_t count) const {
  return reader_.numbers(required(key), field(key), count);
}

namespace detail {

void rethrow_yaml_exception(const std::string& file, const YAML::Exception& e) {
  throw InputError(file, std::max(0, e.mark.line + 1), "unexpected YAML structure: " + e.msg);
}

}  // namespace detail

}  // namespace echoplan
