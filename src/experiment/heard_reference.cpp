#include "experiment/heard_reference.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>

#include "common/error.h"
#include "common/json_fields.h"
#include "common/yaml_reader.h"

namespace echoplan::experiment {

int HeardCounts::right(std::size_t row) const { return heard_as(row, rows[row]); }

int HeardCounts::heard_as(std::size_t row, const std::string& column) const {
  const auto at = std::find(columns.begin(), columns.end(), column);
  return at == columns.end() ? 0 : counts[row][at - columns.begin()];
}

int HeardCounts::total(std::size_t row) const {
  int n = 0;
  for (int c : counts[row]) n += c;
  return n;
}

namespace {

// One action's {object: [counts]} mapping, each list as long as `classes`.
HeardCounts read_action(const YamlReader& f, const std::string& action, const YAML::Node& node,
                        const std::vector<std::string>& classes) {
  const std::string entry = "heard.actions." + action;
  f.expect_map(node, entry);
  HeardCounts h{action, {}, classes, {}};
  for (const auto& row : node) {
    const std::string object = f.name(row.first, "an object's name");
    const std::string what = entry + "." + object;
    std::vector<int> counts;
    for (double x : f.numbers(row.second, what)) {
      if (x < 0 || x != std::floor(x) || x > 1e9)
        throw InputError(f.file(), YamlReader::line_of(row.second),
                         what + ": counts must be whole numbers >= 0");
      counts.push_back(static_cast<int>(x));
    }
    if (counts.size() != classes.size())
      throw InputError(f.file(), YamlReader::line_of(row.second),
                       what + ": expected " + std::to_string(classes.size()) +
                           " counts, one per class of heard.classes");
    h.rows.push_back(object);
    h.counts.push_back(std::move(counts));
  }
  return h;
}

}  // namespace

HeardReference read_heard_reference(const YamlReader& f, const YAML::Node& node) {
  f.expect_map(node, "heard");
  f.only_keys(node, {"classifier", "note", "classes", "actions"}, "heard");
  HeardReference r;
  r.classifier = f.name(f.require(node, "classifier", "heard"), "heard.classifier");
  if (auto n = f.optional(node, "note", "heard")) r.note = f.name(n, "heard.note");
  const std::vector<std::string> classes =
      f.names(f.require(node, "classes", "heard"), "heard.classes");
  const YAML::Node actions = f.require(node, "actions", "heard");
  f.expect_map(actions, "heard.actions");
  for (const auto& a : actions)
    r.actions.push_back(read_action(f, f.name(a.first, "an action's name"), a.second, classes));
  return r;
}

nlohmann::json to_json(const HeardCounts& counts) {
  return {{"action", counts.action},
          {"objects", counts.rows},
          {"heard", counts.columns},
          {"counts", counts.counts}};
}

nlohmann::json to_json(const HeardReference& reference) {
  nlohmann::json actions = nlohmann::json::array();
  for (const HeardCounts& h : reference.actions) actions.push_back(to_json(h));
  return {{"classifier", reference.classifier}, {"note", reference.note}, {"actions", actions}};
}

namespace jf = json_fields;

HeardCounts heard_counts_from_json(const nlohmann::json& j, const std::string& path,
                                   const std::string& source) {
  const jf::JsonSource from(source);
  HeardCounts h;
  h.action = jf::string(jf::member(j, "action", path, from), jf::child(path, "action"), from);
  h.rows = jf::strings(jf::member(j, "objects", path, from), jf::child(path, "objects"), from);
  h.columns = jf::strings(jf::member(j, "heard", path, from), jf::child(path, "heard"), from);
  const std::string where = jf::child(path, "counts");
  const nlohmann::json& counts = jf::array(jf::member(j, "counts", path, from), where, from);
  if (counts.size() != h.rows.size())
    throw InputError(source, 0, where + ": expected a row of counts per object");
  for (std::size_t i = 0; i < counts.size(); ++i)
    h.counts.push_back(jf::integers(counts[i], static_cast<long long>(h.columns.size()),
                                    jf::element(where, i), from));
  return h;
}

HeardReference heard_reference_from_json(const nlohmann::json& j, const std::string& source) {
  const jf::JsonSource from(source);
  const std::string path = "reference.heard";
  HeardReference r;
  r.classifier =
      jf::string(jf::member(j, "classifier", path, from), jf::child(path, "classifier"), from);
  r.note = jf::string(jf::member(j, "note", path, from), jf::child(path, "note"), from);
  const std::string where = jf::child(path, "actions");
  const nlohmann::json& actions = jf::array(jf::member(j, "actions", path, from), where, from);
  for (std::size_t i = 0; i < actions.size(); ++i)
    r.actions.push_back(heard_counts_from_json(actions[i], jf::element(where, i), source));
  return r;
}

}  // namespace echoplan::experiment
