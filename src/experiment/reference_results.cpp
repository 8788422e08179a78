#include "experiment/reference_results.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>

#include "common/error.h"
#include "common/file_io.h"
#include "common/json_fields.h"
#include "common/yaml_reader.h"

namespace echoplan::experiment {

namespace {

const std::vector<std::string> kResultKeys = {"trials", "correct", "mean_discounted_reward",
                                              "mean_steps"};

// The four numbers of a result from mapping `m` (its other keys were checked by the caller).
ReferenceResult read_result(const YamlMapping& m) {
  const YamlReader& f = m.reader();
  ReferenceResult r;
  r.trials = f.non_negative_int(m.required("trials"), m.entry() + ".trials");
  if (r.trials < 1) m.fail(m.required("trials"), "trials must be >= 1");
  r.correct = f.non_negative_int(m.required("correct"), m.entry() + ".correct");
  if (r.correct > r.trials)
    m.fail(m.required("correct"),
           "correct must not exceed trials (" + std::to_string(r.trials) + ")");
  r.mean_discounted_reward = m.number("mean_discounted_reward");
  r.mean_steps = m.number("mean_steps", NumberRange::at_least(0.0));
  return r;
}

ReferenceTotal read_total(const YamlReader& f, const YAML::Node& node, const std::string& entry) {
  const YamlMapping m(f, entry, node);
  std::vector<std::string> keys = kResultKeys;
  keys.push_back("objects");
  m.only_keys(keys);
  ReferenceTotal total;
  total.objects = f.names(m.required("objects"), entry + ".objects");
  total.result = read_result(m);
  return total;
}

ReferenceResults read_reference(const std::string& yaml_text, const std::string& source) {
  const YamlReader f(source);
  const YAML::Node root = parse_yaml(yaml_text, source);
  f.expect_map(root, "the reference");
  f.reject_duplicate_keys(root);
  f.only_keys(root, {"label", "note", "objects", "totals", "heard"}, "the reference");

  ReferenceResults r;
  r.source = source;
  r.label = f.name(f.require(root, "label", "the reference"), "label");
  if (auto n = f.optional(root, "note", "the reference")) r.note = f.name(n, "note");

  const YAML::Node objects = f.require(root, "objects", "the reference");
  f.expect_map(objects, "objects");
  for (const auto& entry : objects) {
    const std::string object = f.name(entry.first, "an object's name");
    const YamlMapping m(f, "objects." + object, entry.second);
    m.only_keys(kResultKeys);
    r.objects[object] = read_result(m);
  }

  if (auto totals = f.optional(root, "totals", "the reference")) {
    f.expect_map(totals, "totals");
    f.only_keys(totals, {"original_objects", "variants", "all"}, "totals");
    if (auto n = f.optional(totals, "original_objects", "totals"))
      r.original_objects = read_total(f, n, "totals.original_objects");
    if (auto n = f.optional(totals, "variants", "totals"))
      r.variants = read_total(f, n, "totals.variants");
    if (auto n = f.optional(totals, "all", "totals")) r.all = read_total(f, n, "totals.all");
  }
  if (auto heard = f.optional(root, "heard", "the reference"))
    r.heard = read_heard_reference(f, heard);
  return r;
}

nlohmann::json result_json(const ReferenceResult& r) {
  return {{"trials", r.trials},
          {"correct", r.correct},
          {"mean_discounted_reward", r.mean_discounted_reward},
          {"mean_steps", r.mean_steps}};
}

namespace jf = json_fields;

ReferenceResult result_from_json(const nlohmann::json& j, const std::string& path,
                                 const jf::JsonSource& source) {
  const auto field = [&](const char* key) -> const nlohmann::json& {
    return jf::member(j, key, path, source);
  };
  return {jf::integer(field("trials"), 0, 1 << 30, jf::child(path, "trials"), source),
          jf::integer(field("correct"), 0, 1 << 30, jf::child(path, "correct"), source),
          jf::number(field("mean_discounted_reward"), jf::child(path, "mean_discounted_reward"),
                     source),
          jf::number(field("mean_steps"), jf::child(path, "mean_steps"), source)};
}

std::optional<ReferenceTotal> total_from_json(const nlohmann::json& totals, const char* key,
                                              const jf::JsonSource& source) {
  const std::string path = jf::child("reference.totals", key);
  const nlohmann::json* t = jf::optional_member(totals, key, "reference.totals", source);
  if (!t) return std::nullopt;
  return ReferenceTotal{
      jf::strings(jf::member(*t, "objects", path, source), jf::child(path, "objects"), source),
      result_from_json(*t, path, source)};
}

}  // namespace

ReferenceResults parse_reference_results(const std::string& yaml_text, const std::string& source) {
  return read_yaml_guarded(source, [&] { return read_reference(yaml_text, source); });
}

ReferenceResults load_reference_results(const std::string& path) {
  return parse_reference_results(read_text_file(path, "reference file"), path);
}

nlohmann::json to_json(const ReferenceResults& reference) {
  nlohmann::json j;
  j["source"] = reference.source;
  j["label"] = reference.label;
  j["note"] = reference.note;
  j["objects"] = nlohmann::json::object();
  for (const auto& [object, result] : reference.objects) j["objects"][object] = result_json(result);
  j["totals"] = nlohmann::json::object();
  auto add_total = [&](const char* key, const std::optional<ReferenceTotal>& total) {
    if (!total) return;
    nlohmann::json t = result_json(total->result);
    t["objects"] = total->objects;
    j["totals"][key] = std::move(t);
  };
  add_total("original_objects", reference.original_objects);
  add_total("variants", reference.variants);
  add_total("all", reference.all);
  if (reference.heard) j["heard"] = to_json(*reference.heard);
  return j;
}

ReferenceResults reference_results_from_json(const nlohmann::json& j, const std::string& source) {
  const jf::JsonSource from(source);
  const auto text = [&](const char* key) {
    return jf::string(jf::member(j, key, "reference", from), jf::child("reference", key), from);
  };
  ReferenceResults r;
  r.source = text("source");
  r.label = text("label");
  r.note = text("note");
  const nlohmann::json& objects = jf::member(j, "objects", "reference", from);
  if (!objects.is_object())
    throw InputError(source, 0, "reference.objects: expected an object of results by object");
  for (const auto& [object, result] : objects.items())
    r.objects[object] = result_from_json(result, jf::child("reference.objects", object), from);
  const nlohmann::json& totals = jf::member(j, "totals", "reference", from);
  r.original_objects = total_from_json(totals, "original_objects", from);
  r.variants = total_from_json(totals, "variants", from);
  r.all = total_from_json(totals, "all", from);
  if (const nlohmann::json* heard = jf::optional_member(j, "heard", "reference", from))
    r.heard = heard_reference_from_json(*heard, source);
  return r;
}

}  // namespace echoplan::experiment
