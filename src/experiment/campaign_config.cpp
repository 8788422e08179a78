#include "experiment/campaign_config.h"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "common/data_dir.h"
#include "common/error.h"
#include "common/file_io.h"
#include "common/json_fields.h"
#include "common/stable_hash.h"
#include "common/yaml_reader.h"
#include "perception/observation_model.h"
#include "solvers/baseline_strategies.h"
#include "solvers/make_solver.h"

namespace echoplan::experiment {

namespace {

namespace fs = std::filesystem;

// A path from the file, relative to the file's folder unless absolute.
std::string resolve(const std::string& source, const std::string& path) {
  if (path.empty() || fs::path(path).is_absolute()) return path;
  return (fs::path(source).parent_path() / path).lexically_normal().string();
}

bool is_label(const std::string& name) {
  if (name.empty()) return false;
  for (char c : name)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-')) return false;
  return true;
}

// A fingerprint of a file's bytes, as 16 hex digits; "" when the path is empty.
std::string content_hash(const std::string& path, const CampaignConfig::FileText& file_text) {
  if (path.empty()) return "";
  return fmt::format("{:016x}", stable_hash(file_text(path)));
}

CampaignConfig read_campaign(const std::string& yaml_text, const std::string& source);

// A fingerprint of every file under `folder` (paths relative to it, in sorted order, and contents):
// a dataset world's data is part of the campaign's identity.
std::uint64_t folder_hash(const std::string& folder) {
  std::vector<fs::path> files;
  std::error_code error;
  for (fs::recursive_directory_iterator it(folder, error), end; !error && it != end;
       it.increment(error))
    if (it->is_regular_file(error)) files.push_back(it->path());
  if (error) throw InputError(folder, 0, "cannot list the data folder: " + error.message());
  std::sort(files.begin(), files.end());
  std::string all;
  for (const fs::path& file : files) {
    const std::string text = read_text_file(file.string(), "data file");
    all += fs::relative(file, folder).generic_string();
    all += fmt::format("\n{:016x}\n", stable_hash(text));
  }
  return stable_hash(all);
}

}  // namespace

namespace {

constexpr std::array<WorldKind, 3> kWorldKinds{{{WorldType::model, "model", false},
                                                {WorldType::simulated, "simulated", false},
                                                {WorldType::dataset, "dataset", true}}};

}  // namespace

const WorldKind& world_kind(WorldType type) {
  for (const WorldKind& kind : kWorldKinds)
    if (kind.type == type) return kind;
  throw std::invalid_argument("world_kind: a WorldType without a kind");
}

const WorldKind& world_kind(std::string_view word) {
  std::vector<std::string> words;
  for (const WorldKind& kind : kWorldKinds) {
    if (kind.word == word) return kind;
    words.emplace_back(kind.word);
  }
  throw InputError(fmt::format("world type '{}' is not one of: {}", word, fmt::join(words, ", ")));
}

const char* to_string(WorldType type) { return world_kind(type).word; }

bool WorldConfig::recorded_data() const { return world_kind(type).recorded_data; }

int CampaignConfig::total_trials() const {
  int per_arm = 0;
  for (const ObjectGroup& g : groups) per_arm += g.trials;
  return per_arm * static_cast<int>(arms.size());
}

nlohmann::json CampaignConfig::identity() const {
  return identity([](const std::string& path) { return read_text_file(path, "file"); });
}

nlohmann::json CampaignConfig::identity(const FileText& file_text) const {
  const auto content_hash = [&](const std::string& path) {
    return experiment::content_hash(path, file_text);
  };
  nlohmann::json j;
  j["seed"] = seed;
  for (const CampaignArm& arm : arms) {
    nlohmann::json a = {{"name", arm.name},
                        {"problem_sha", content_hash(arm.problem)},
                        {"calibrate", arm.calibrate}};
    // Only when not the planner: campaigns written before strategies existed keep their identity.
    if (arm.strategy != kPlanStrategy) a["strategy"] = arm.strategy;
    j["arms"].push_back(std::move(a));
  }
  j["world"] = {{"type", to_string(world.type)}, {"problem_sha", content_hash(world.problem)}};
  if (world.recorded_data()) {
    j["world"]["data_sha"] = fmt::format("{:016x}", folder_hash(world.data));
    j["world"]["hold_out"] = perception::hold_out_name(world.hold_out);
    j["world"]["groups_sha"] = content_hash(world.groups);
    // Only when frozen: fold campaigns written before frozen models existed keep their identity.
    if (!world.model.empty()) j["world"]["model_sha"] = content_hash(world.model);
    j["rewards"] = {{"right", rewards.right}, {"wrong", rewards.wrong}, {"sense", rewards.sense}};
    // Only when priced: campaigns written before costs existed keep their identity.
    if (!rewards.costs.empty()) j["rewards"]["costs"] = rewards.costs;
  }
  j["training_set"] = {{"recordings_per_pair", training.recordings_per_pair},
                       {"objects", training.objects},
                       {"actions", training.actions},
                       {"recordings", training.recordings},
                       {"model_sha", content_hash(training.model)},
                       {"classifier", training.classifier},
                       {"table", training.table},
                       {"catalogue_sha", content_hash(training.catalogue)},
                       {"sim_config_sha", content_hash(training.sim_config)}};
  for (const ObjectGroup& g : groups)
    j["trials"].push_back({{"object", g.object}, {"plays", g.plays}, {"trials", g.trials}});
  j["planner"] = {{"solver", planner.solver},
                  {"episodes", planner.episodes},
                  {"step_ms", planner.step_ms},
                  {"max_steps", planner.max_steps}};
  return j;
}

CampaignConfig parse_campaign_config(const std::string& yaml_text, const std::string& source) {
  return read_yaml_guarded(source, [&] { return read_campaign(yaml_text, source); });
}

namespace {

// An arm's strategy: the planner or one of the solver factory's fixed strategies.
std::string read_strategy(const YamlReader& f, const YAML::Node& n) {
  const std::string strategy = f.name(n, "strategy");
  if (strategy == kPlanStrategy) return strategy;
  const std::vector<std::string> fixed = solvers::strategy_names();
  if (std::find(fixed.begin(), fixed.end(), strategy) == fixed.end())
    f.fail(n, fmt::format("strategy '{}' is not one of: {}, {}", strategy, kPlanStrategy,
                          fmt::join(fixed, ", ")));
  return strategy;
}

CampaignArm read_arm(const YamlReader& f, const YAML::Node& a, const std::string& source,
                     bool recorded_data) {
  f.expect_map(a, "an arm");
  f.only_keys(a, {"name", "problem", "calibrate", "strategy"}, "an arm");
  CampaignArm arm;
  arm.name = f.name(f.require(a, "name", "an arm"), "arm name");
  if (!is_label(arm.name))
    f.fail(a, "arm name '" + arm.name + "' may hold only letters, digits, '_' and '-'");
  if (auto n = f.optional(a, "strategy", "an arm")) arm.strategy = read_strategy(f, n);
  if (recorded_data) {
    // Every arm of a dataset world decides with the fold's problem, calibrated on the fold.
    for (const char* key : {"problem", "calibrate"})
      if (auto n = f.optional(a, key, "an arm"))
        f.fail(n, fmt::format("{} is not for a dataset world's arms: each fold's problem is built "
                              "and calibrated from the data",
                              key));
    return arm;
  }
  arm.problem = resolve(source, f.name(f.require(a, "problem", "an arm"), "arm problem"));
  if (auto n = f.optional(a, "calibrate", "an arm")) arm.calibrate = f.boolean(n, "calibrate");
  return arm;
}

std::vector<CampaignArm> read_arms(const YamlReader& f, const YAML::Node& root,
                                   const std::string& source, bool recorded_data) {
  const YAML::Node arms = f.require(root, "arms", "the campaign");
  if (!arms.IsSequence() || arms.size() == 0) f.fail(arms, "arms must be a non-empty list");
  std::vector<CampaignArm> read;
  for (const YAML::Node& a : arms) {
    CampaignArm arm = read_arm(f, a, source, recorded_data);
    for (const CampaignArm& other : read)
      if (other.name == arm.name) f.fail(a, "two arms are named '" + arm.name + "'");
    read.push_back(std::move(arm));
  }
  return read;
}

WorldType read_world_type(const YamlReader& f, const YAML::Node& world) {
  const YAML::Node type = f.require(world, "type", "world");
  try {
    return world_kind(f.name(type, "world type")).type;
  } catch (const InputError& e) {
    f.fail(type, e.problem());
  }
}

// A dataset world: where the data is, what a trial holds out, what the objects are sorted by.
void read_dataset_world(const YamlReader& f, const YAML::Node& world, const std::string& source,
                        WorldConfig& w) {
  f.only_keys(world, {"type", "data", "hold_out", "groups", "model"}, "world");
  const YAML::Node data = f.require(world, "data", "world");
  w.data = resolve(source, f.name(data, "data"));
  std::error_code error;
  if (!fs::is_directory(w.data, error))
    f.fail(data, "data folder '" + w.data + "' does not exist (a feature set or recordings tree)");
  if (auto n = f.optional(world, "hold_out", "world")) {
    try {
      w.hold_out = perception::parse_hold_out(f.name(n, "hold_out"));
    } catch (const InputError& e) {
      f.fail(n, e.problem());
    }
  }
  if (auto n = f.optional(world, "groups", "world")) {
    w.groups = resolve(source, f.name(n, "groups"));
    if (!fs::is_regular_file(w.groups, error))
      f.fail(n, "groups file '" + w.groups + "' does not exist");
  }
  if (w.hold_out == perception::HoldOut::object && w.groups.empty())
    f.fail(world, "hold_out: object needs groups: a novel object can only be sorted by its group");
  if (auto n = f.optional(world, "model", "world")) {
    w.model = resolve(source, f.name(n, "model"));
    if (!fs::is_regular_file(w.model, error))
      f.fail(n, "model file '" + w.model +
                    "' does not exist (`echoplan train --data DIR --out "
                    "MODEL` writes one)");
  }
}

WorldConfig read_world(const YamlReader& f, const YAML::Node& root, const std::string& source) {
  const YAML::Node world = f.require(root, "world", "the campaign");
  f.expect_map(world, "world");
  WorldConfig w;
  w.type = read_world_type(f, world);
  if (w.recorded_data()) {
    read_dataset_world(f, world, source, w);
    return w;
  }
  f.only_keys(world, {"type", "problem"}, "world");
  w.problem = resolve(source, f.name(f.require(world, "problem", "world"), "world problem"));
  return w;
}

// `task: {costs: {BEHAVIOUR: C, ...}}`: a cost (>= 0) per priced behaviour. Which behaviours the
// data has is known only once it is read (loop::dataset_problem checks the names then).
std::map<std::string, double> read_costs(const YamlReader& f, const YAML::Node& costs) {
  f.expect_map(costs, "task.costs");
  std::map<std::string, double> priced;
  for (auto it = costs.begin(); it != costs.end(); ++it) {
    const std::string behaviour = f.name(it->first, "task.costs behaviour");
    priced[behaviour] = f.number(it->second, "task.costs." + behaviour, NumberRange::at_least(0.0));
  }
  return priced;
}

// `task: {rewards: {right, wrong, sense}, costs: {...}}`, a dataset world's rewards (one of the two
// at least; the other keeps its defaults).
loop::TaskRewards read_task(const YamlReader& f, const YAML::Node& task) {
  f.expect_map(task, "task");
  f.only_keys(task, {"rewards", "costs"}, "task");
  loop::TaskRewards rewards;
  if (auto c = f.optional(task, "costs", "task")) rewards.costs = read_costs(f, c);
  const YAML::Node r = f.optional(task, "rewards", "task");
  if (!r) {
    if (rewards.costs.empty()) f.fail(task, "task: give rewards, costs or both");
    return rewards;
  }
  f.expect_map(r, "task.rewards");
  f.only_keys(r, {"right", "wrong", "sense"}, "task.rewards");
  if (auto n = f.optional(r, "right", "task.rewards")) rewards.right = f.number(n, "right");
  if (auto n = f.optional(r, "wrong", "task.rewards")) rewards.wrong = f.number(n, "wrong");
  if (auto n = f.optional(r, "sense", "task.rewards")) rewards.sense = f.number(n, "sense");
  if (!(rewards.right > rewards.wrong)) f.fail(r, "task.rewards: right must be greater than wrong");
  return rewards;
}

// How the classifier is trained (or the trained model used instead): the `training_set` mapping.
TrainingSetConfig read_training_set(const YamlReader& f, const YAML::Node& t,
                                    const std::string& source) {
  f.expect_map(t, "training_set");
  f.only_keys(t,
              {"recordings_per_pair", "objects", "actions", "recordings", "model", "classifier",
               "table", "catalogue", "sim_config"},
              "training_set");
  TrainingSetConfig training;
  if (auto n = f.optional(t, "model", "training_set"))
    training.model = resolve(source, f.name(n, "model"));
  // Keys that say how this campaign trains mean nothing next to a trained model: an error, not
  // a silently ignored setting.
  for (const char* key : {"classifier", "table"})
    if (auto n = f.optional(t, key, "training_set"); n && !training.model.empty())
      f.fail(n, fmt::format("{} chooses how this campaign trains; with model: the model file "
                            "has its own",
                            key));
  if (auto n = f.optional(t, "classifier", "training_set"))
    training.classifier = f.name(n, "classifier");
  if (auto n = f.optional(t, "table", "training_set")) {
    training.table = f.name(n, "table");
    const auto& names = perception::clip_table_estimate_names();
    if (std::find(names.begin(), names.end(), training.table) == names.end())
      f.fail(n,
             fmt::format("table '{}' is not one of: {}", training.table, fmt::join(names, ", ")));
  }
  if (auto n = f.optional(t, "recordings", "training_set"))
    training.recordings = resolve(source, f.name(n, "recordings"));
  if (auto n = f.optional(t, "recordings_per_pair", "training_set"))
    training.recordings_per_pair = f.non_negative_int(n, "recordings_per_pair");
  if (auto n = f.optional(t, "objects", "training_set")) training.objects = f.names(n, "objects");
  if (auto n = f.optional(t, "actions", "training_set")) training.actions = f.names(n, "actions");
  if (auto n = f.optional(t, "catalogue", "training_set"))
    training.catalogue = resolve(source, f.name(n, "catalogue"));
  if (auto n = f.optional(t, "sim_config", "training_set"))
    training.sim_config = resolve(source, f.name(n, "sim_config"));
  return training;
}

std::vector<ObjectGroup> read_trial_groups(const YamlReader& f, const YAML::Node& root) {
  const YAML::Node trials = f.require(root, "trials", "the campaign");
  if (!trials.IsSequence() || trials.size() == 0)
    f.fail(trials, "trials must be a non-empty list of object groups");
  std::vector<ObjectGroup> groups;
  for (const YAML::Node& g : trials) {
    f.expect_map(g, "a trial group");
    f.only_keys(g, {"object", "plays", "trials"}, "a trial group");
    ObjectGroup group;
    group.object = f.name(f.require(g, "object", "a trial group"), "object");
    group.plays = group.object;
    if (auto n = f.optional(g, "plays", "a trial group")) group.plays = f.name(n, "plays");
    if (auto n = f.optional(g, "trials", "a trial group")) {
      group.trials = f.non_negative_int(n, "trials");
      if (group.trials < 1) f.fail(n, "trials must be >= 1");
    }
    for (const ObjectGroup& other : groups)
      if (other.object == group.object)
        f.fail(g, "object '" + group.object + "' has two trial groups");
    groups.push_back(group);
  }
  return groups;
}

PlannerConfig read_planner(const YamlReader& f, const YAML::Node& root) {
  const YAML::Node p = f.optional(root, "planner", "campaign");
  if (!p) f.fail(root, "missing key 'planner' (its budget: episodes or step_ms)");
  f.expect_map(p, "planner");
  f.only_keys(p, {"solver", "episodes", "step_ms", "max_steps"}, "planner");
  PlannerConfig planner;
  if (auto n = f.optional(p, "solver", "planner")) planner.solver = f.name(n, "solver");
  // The online solvers: a campaign plans within each trial's time, not from a stored policy.
  const std::vector<std::string> online = solvers::solver_names();
  if (std::find(online.begin(), online.end(), planner.solver) == online.end())
    f.fail(p, fmt::format("planner solver '{}' is not one of: {}", planner.solver,
                          fmt::join(online, ", ")));
  if (auto n = f.optional(p, "episodes", "planner"))
    planner.episodes = f.non_negative_int(n, "episodes");
  if (auto n = f.optional(p, "step_ms", "planner"))
    planner.step_ms = f.non_negative_int(n, "step_ms");
  if (auto n = f.optional(p, "max_steps", "planner"))
    planner.max_steps = f.non_negative_int(n, "max_steps");
  if ((planner.episodes > 0) == (planner.step_ms > 0))
    f.fail(p, "give exactly one planning budget: episodes (reproducible) or step_ms");
  if (planner.max_steps < 1) f.fail(p, "max_steps must be >= 1");
  return planner;
}

// The reference file named by `reference:`, read whole (its mistakes name its own lines).
std::optional<ReferenceResults> read_reference(const YamlReader& f, const YAML::Node& root,
                                               const std::string& source) {
  const YAML::Node n = f.optional(root, "reference", "campaign");
  if (!n) return std::nullopt;
  const std::string path = resolve(source, f.name(n, "reference"));
  std::error_code error;
  if (!fs::is_regular_file(path, error)) f.fail(n, "reference file '" + path + "' does not exist");
  return load_reference_results(path);
}

// What a dataset world's campaign takes instead of trial groups and a training set: the task's
// rewards (its trials are the data's sessions; its classifiers are fitted per fold, or frozen).
void read_dataset_sections(const YamlReader& f, const YAML::Node& root, CampaignConfig& c) {
  if (auto t = f.optional(root, "trials", "campaign"))
    f.fail(t, "a dataset world's trials are the data's (object, session) pairs: remove trials");
  if (auto t = f.optional(root, "training_set", "campaign")) {
    if (!c.world.model.empty())
      f.fail(t, "training_set: the world's model is frozen (world.model); nothing is trained");
    f.only_keys(t, {"classifier"}, "training_set (a dataset world fits its classifiers per fold)");
  }
  if (auto t = f.optional(root, "task", "campaign")) c.rewards = read_task(f, t);
}

CampaignConfig read_campaign(const std::string& yaml_text, const std::string& source) {
  const YamlReader f(source);
  const YAML::Node root = parse_yaml(yaml_text, source);
  f.expect_map(root, "the campaign");
  f.reject_duplicate_keys(root);
  f.only_keys(root,
              {"seed", "arms", "world", "task", "training_set", "trials", "planner", "reference"},
              "the campaign");

  CampaignConfig c;
  c.source = source;
  if (auto n = f.optional(root, "seed", "campaign")) {
    try {
      c.seed = n.as<std::uint64_t>();
    } catch (const YAML::Exception&) {
      f.fail(n, "seed must be a non-negative integer");
    }
  }
  c.world = read_world(f, root, source);
  c.arms = read_arms(f, root, source, c.world.recorded_data());
  if (auto t = f.optional(root, "training_set", "campaign"))
    c.training = read_training_set(f, t, source);
  if (c.world.recorded_data()) {
    read_dataset_sections(f, root, c);
  } else {
    c.groups = read_trial_groups(f, root);
    if (auto t = f.optional(root, "task", "campaign"))
      f.fail(t,
             "task is for dataset worlds; the problem file gives a model or simulated world's "
             "rewards");
  }
  c.planner = read_planner(f, root);
  c.reference = read_reference(f, root, source);
  return c;
}

}  // namespace

CampaignConfig load_campaign_config(const std::string& path) {
  return parse_campaign_config(read_text_file(path, "campaign file"), path);
}

nlohmann::json to_json(const CampaignConfig& c) {
  nlohmann::json j;
  j["source"] = c.source;
  j["seed"] = c.seed;
  for (const CampaignArm& arm : c.arms) {
    nlohmann::json a = {{"name", arm.name}, {"problem", arm.problem}, {"calibrate", arm.calibrate}};
    if (arm.strategy != kPlanStrategy) a["strategy"] = arm.strategy;
    j["arms"].push_back(std::move(a));
  }
  j["world"] = {{"type", to_string(c.world.type)}, {"problem", c.world.problem}};
  if (c.world.recorded_data()) {
    j["world"]["data"] = c.world.data;
    j["world"]["hold_out"] = perception::hold_out_name(c.world.hold_out);
    j["world"]["groups"] = c.world.groups;
    if (!c.world.model.empty()) j["world"]["model"] = c.world.model;
    j["rewards"] = {
        {"right", c.rewards.right}, {"wrong", c.rewards.wrong}, {"sense", c.rewards.sense}};
    if (!c.rewards.costs.empty()) j["rewards"]["costs"] = c.rewards.costs;
  }
  j["training_set"] = {{"recordings_per_pair", c.training.recordings_per_pair},
                       {"objects", c.training.objects},
                       {"actions", c.training.actions},
                       {"recordings", c.training.recordings},
                       {"model", c.training.model},
                       {"classifier", c.training.classifier},
                       {"table", c.training.table},
                       {"catalogue", c.training.catalogue},
                       {"sim_config", c.training.sim_config}};
  j["trials"] = nlohmann::json::array();  // a dataset world's file has none (the data has them)
  for (const ObjectGroup& g : c.groups)
    j["trials"].push_back({{"object", g.object}, {"plays", g.plays}, {"trials", g.trials}});
  j["planner"] = {{"solver", c.planner.solver},
                  {"episodes", c.planner.episodes},
                  {"step_ms", c.planner.step_ms},
                  {"max_steps", c.planner.max_steps}};
  if (c.reference) j["reference"] = to_json(*c.reference);
  return j;
}

namespace {

namespace jf = json_fields;

std::vector<CampaignArm> arms_from_json(const nlohmann::json& j, const jf::JsonSource& source) {
  std::vector<CampaignArm> arms;
  const nlohmann::json& list = jf::array(jf::member(j, "arms", "", source), "arms", source);
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string path = jf::element("arms", i);
    CampaignArm arm;
    arm.name = jf::string(jf::member(list[i], "name", path, source), path + ".name", source);
    arm.problem =
        jf::string(jf::member(list[i], "problem", path, source), path + ".problem", source);
    arm.calibrate =
        jf::boolean(jf::member(list[i], "calibrate", path, source), path + ".calibrate", source);
    if (const auto* s = jf::optional_member(list[i], "strategy", path, source))
      arm.strategy = jf::string(*s, path + ".strategy", source);
    arms.push_back(std::move(arm));
  }
  return arms;
}

WorldConfig world_from_json(const nlohmann::json& j, const jf::JsonSource& source) {
  const nlohmann::json& w = jf::member(j, "world", "", source);
  WorldConfig world;
  const std::string type = jf::string(jf::member(w, "type", "world", source), "world.type", source);
  try {
    world.type = world_kind(type).type;
  } catch (const InputError& e) {
    throw InputError(source.file, source.line, "world.type: " + e.problem());
  }
  world.problem = jf::string(jf::member(w, "problem", "world", source), "world.problem", source);
  if (world.recorded_data()) {
    const auto text = [&](const char* key) {
      return jf::string(jf::member(w, key, "world", source), jf::child("world", key), source);
    };
    world.data = text("data");
    try {
      world.hold_out = perception::parse_hold_out(text("hold_out"));
    } catch (const InputError& e) {
      throw InputError(source.file, source.line, "world.hold_out: " + e.problem());
    }
    world.groups = text("groups");
    if (w.contains("model")) world.model = text("model");
  }
  return world;
}

TrainingSetConfig training_from_json(const nlohmann::json& j, const jf::JsonSource& source) {
  const nlohmann::json& t = jf::member(j, "training_set", "", source);
  const auto text = [&](const char* key) {
    return jf::string(jf::member(t, key, "training_set", source), jf::child("training_set", key),
                      source);
  };
  TrainingSetConfig training;
  training.recordings_per_pair =
      jf::integer(jf::member(t, "recordings_per_pair", "training_set", source), 0, 1 << 30,
                  "training_set.recordings_per_pair", source);
  training.objects =
      jf::strings(jf::member(t, "objects", "training_set", source), "training_set.objects", source);
  training.actions =
      jf::strings(jf::member(t, "actions", "training_set", source), "training_set.actions", source);
  training.recordings = text("recordings");
  training.model = text("model");
  training.classifier = text("classifier");
  // Absent in campaign folders written before the option existed (they trained on counts).
  if (const auto* table = jf::optional_member(t, "table", "training_set", source))
    training.table = jf::string(*table, "training_set.table", source);
  training.catalogue = text("catalogue");
  training.sim_config = text("sim_config");
  return training;
}

std::vector<ObjectGroup> groups_from_json(const nlohmann::json& j, const jf::JsonSource& source) {
  std::vector<ObjectGroup> groups;
  const nlohmann::json& list = jf::array(jf::member(j, "trials", "", source), "trials", source);
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string path = jf::element("trials", i);
    groups.push_back(
        {jf::string(jf::member(list[i], "object", path, source), path + ".object", source),
         jf::string(jf::member(list[i], "plays", path, source), path + ".plays", source),
         jf::integer(jf::member(list[i], "trials", path, source), 1, 1 << 30, path + ".trials",
                     source)});
  }
  return groups;
}

PlannerConfig planner_from_json(const nlohmann::json& j, const jf::JsonSource& source) {
  const nlohmann::json& p = jf::member(j, "planner", "", source);
  PlannerConfig planner;
  planner.solver = jf::string(jf::member(p, "solver", "planner", source), "planner.solver", source);
  planner.episodes =
      jf::integer64(jf::member(p, "episodes", "planner", source), "planner.episodes", source);
  planner.step_ms =
      jf::integer64(jf::member(p, "step_ms", "planner", source), "planner.step_ms", source);
  planner.max_steps = jf::integer(jf::member(p, "max_steps", "planner", source), 1, 1 << 30,
                                  "planner.max_steps", source);
  return planner;
}

}  // namespace

CampaignConfig campaign_config_from_json(const nlohmann::json& j, const std::string& source) {
  const jf::JsonSource from(source);
  CampaignConfig c;
  c.source = jf::string(jf::member(j, "source", "", from), "source", from);
  c.seed = jf::unsigned64(jf::member(j, "seed", "", from), "seed", from);
  c.arms = arms_from_json(j, from);
  c.world = world_from_json(j, from);
  c.training = training_from_json(j, from);
  c.groups = groups_from_json(j, from);
  c.planner = planner_from_json(j, from);
  if (const auto* r = jf::optional_member(j, "rewards", "", from)) {
    const auto reward = [&](const char* key) {
      return jf::number(jf::member(*r, key, "rewards", from), jf::child("rewards", key), from);
    };
    c.rewards = {reward("right"), reward("wrong"), reward("sense"), {}};
    // Absent when unpriced, and in folders written before costs existed.
    if (const auto* costs = jf::optional_member(*r, "costs", "rewards", from))
      for (const auto& [behaviour, cost] : costs->items())
        c.rewards.costs[behaviour] =
            jf::number(cost, jf::child(jf::child("rewards", "costs"), behaviour), from);
  }
  // Absent when the campaign names no reference, and in folders written before the key existed.
  if (j.contains("reference")) c.reference = reference_results_from_json(j["reference"], source);
  return c;
}

std::string default_campaign_path() {
  const std::string local = "experiments/chapter5.yaml";
  if (fs::exists(local)) return local;
  return shipped_file("experiments/chapter5.yaml");
}

}  // namespace echoplan::experiment
