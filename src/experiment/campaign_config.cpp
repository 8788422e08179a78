#include "experiment/campaign_config.h"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <array>
#include <filesystem>

#include "common/data_dir.h"
#include "common/error.h"
#include "common/file_io.h"
#include "common/json_fields.h"
#include "common/yaml_reader.h"
#include "experiment/campaign_arms.h"
#include "experiment/config_fields.h"
#include "perception/fit_observation_model.h"
#include "signal/series_features.h"
#include "sim/background_noise.h"
#include "solvers/baseline_strategies.h"
#include "solvers/leaf_value.h"
#include "solvers/make_solver.h"
#include "solvers/search_tree.h"

namespace echoplan::experiment {

namespace {

namespace fs = std::filesystem;
using config_fields::Field;
using config_fields::Identity;
using config_fields::Text;
using config_fields::Worlds;

constexpr std::array<WorldKind, 3> kWorldKinds{{{WorldType::model, "model", false},
                                                {WorldType::simulated, "simulated", false},
                                                {WorldType::dataset, "dataset", true}}};

// The campaign file, described once (config_fields.h): what each section holds, in which worlds,
// and how each field enters the identity.

std::vector<std::string> observation_choices() { return perception::observation_kind_names(); }

std::vector<std::string> leaf_choices() { return solvers::leaf_mode_names(); }

std::vector<std::string> unheard_choices() {
  std::vector<std::string> choices = solvers::unheard_outcomes_names();
  choices.emplace_back(kUnheardByPlay);
  return choices;
}

std::vector<std::string> strategy_choices() {
  std::vector<std::string> choices{kPlanStrategy};
  for (const std::string& name : solvers::strategy_names()) choices.push_back(name);
  return choices;
}

// A series features spec in its canonical form (presets spelled out).
std::string series_spec(const std::string& text) {
  return signal::parse_series_features(text).spec();
}

const char* const kFoldProblem =
    "not for a dataset world's arms: each fold's problem is built and calibrated from the data";
const char* const kRecordedOnly = "only for a dataset world (recorded data)";
const char* const kFitsPerFold = "not for a dataset world: it fits its classifiers on each fold";

const std::vector<Field<CampaignArm>>& arm_fields() {
  static const std::vector<Field<CampaignArm>> fields{
      {.key = "name", .member = &CampaignArm::name, .text = Text::label, .required = true},
      {.key = "problem",
       .member = &CampaignArm::problem,
       .identity = Identity::file_hash,
       .worlds = Worlds::problem_files,
       .text = Text::path,
       .required = true,
       .elsewhere = kFoldProblem},
      {.key = "calibrate",
       .member = &CampaignArm::calibrate,
       .worlds = Worlds::problem_files,
       .elsewhere = kFoldProblem},
      // Left out of the identity at its default: campaigns written before it existed.
      {.key = "trained_in_noise",
       .member = &CampaignArm::trained_in_noise,
       .identity = Identity::unless_default},
      // Left out of the identity at its default: campaigns written before it existed.
      {.key = "trained_on_surfaces",
       .member = &CampaignArm::trained_on_surfaces,
       .identity = Identity::unless_default,
       .worlds = Worlds::problem_files,
       .elsewhere = kFitsPerFold},
      // Left out of the identity for the planner: campaigns written before strategies existed.
      {.key = "strategy",
       .member = &CampaignArm::strategy,
       .identity = Identity::unless_default,
       .choices = strategy_choices},
      // Left out of the identity at its default: campaigns written before grades existed.
      {.key = "observations",
       .member = &CampaignArm::observations,
       .identity = Identity::unless_default,
       .choices = observation_choices},
      // Left out of the identity at its default: campaigns written before it existed.
      {.key = "lookalike",
       .member = &CampaignArm::lookalike,
       .identity = Identity::unless_default,
       .worlds = Worlds::recorded_data,
       .elsewhere = "only for a dataset world: its folds' models fit the share of objects that "
                    "sound like another class"},
      // Left out of the identity at its default: campaigns written before it existed.
      {.key = "modalities",
       .member = &CampaignArm::modalities,
       .identity = Identity::unless_default,
       .worlds = Worlds::recorded_data,
       .elsewhere = "only for a dataset world: its folds' models are fitted on the data's "
                    "modalities"},
      // Left out of the identity at its default: campaigns written before it existed.
      {.key = "leaf",
       .member = &CampaignArm::leaf,
       .identity = Identity::unless_default,
       .choices = leaf_choices},
      // Left out of the identity at its default: campaigns written before it existed.
      {.key = "unheard",
       .member = &CampaignArm::unheard,
       .identity = Identity::unless_default,
       .choices = unheard_choices},
  };
  return fields;
}

// `noise: {sources: [...], ebr_db: X, talkers: N}` in the world or the training set.
const std::vector<Field<NoiseConfig>>& noise_fields() {
  static const std::vector<Field<NoiseConfig>> fields{
      {.key = "sources", .member = &NoiseConfig::sources, .required = true},
      {.key = "ebr_db", .member = &NoiseConfig::ebr_db},
      {.key = "talkers", .member = &NoiseConfig::talkers, .identity = Identity::unless_default},
  };
  return fields;
}

const std::vector<Field<WorldConfig>>& world_fields() {
  static const std::vector<Field<WorldConfig>> fields{
      {.key = "problem",
       .member = &WorldConfig::problem,
       .identity = Identity::file_hash,
       .worlds = Worlds::problem_files,
       .text = Text::path,
       .required = true,
       .elsewhere = "not for a dataset world: each fold's problem is built from the data"},
      {.key = "data",
       .member = &WorldConfig::data,
       .identity = Identity::data_hash,
       .worlds = Worlds::recorded_data,
       .text = Text::folder,
       .required = true,
       .elsewhere = kRecordedOnly},
      {.key = "hold_out",
       .member = &WorldConfig::hold_out,
       .worlds = Worlds::recorded_data,
       .elsewhere = kRecordedOnly},
      {.key = "groups",
       .member = &WorldConfig::groups,
       .identity = Identity::file_hash,
       .worlds = Worlds::recorded_data,
       .text = Text::file,
       .elsewhere = kRecordedOnly},
      // Left out of the identity at its default: campaigns written before it existed.
      {.key = "series",
       .member = &WorldConfig::series,
       .identity = Identity::unless_default,
       .worlds = Worlds::recorded_data,
       .canonical = series_spec,
       .elsewhere = kRecordedOnly},
      {.key = "model",
       .member = &WorldConfig::model,
       .identity = Identity::file_hash,
       .worlds = Worlds::recorded_data,
       .text = Text::file,
       .elsewhere = kRecordedOnly},
  };
  return fields;
}

// The task's own keys besides `rewards` and `requires`: a cost (>= 0) per priced behaviour. Which
// behaviours the data has is known only once it is read (loop::dataset_problem checks the names
// then). Left out of the identity when none is priced: campaigns written before costs existed keep
// theirs.
const std::vector<Field<loop::TaskSpec>>& task_fields() {
  static const std::vector<Field<loop::TaskSpec>> fields{
      {.key = "costs", .member = &loop::TaskSpec::costs, .identity = Identity::unless_default},
  };
  return fields;
}

const std::vector<Field<loop::TaskSpec>>& reward_fields() {
  static const std::vector<Field<loop::TaskSpec>> fields{
      {.key = "right", .member = &loop::TaskSpec::right},
      {.key = "wrong", .member = &loop::TaskSpec::wrong},
      {.key = "sense", .member = &loop::TaskSpec::sense},
  };
  return fields;
}

const std::vector<Field<TrainingSetConfig>>& training_fields() {
  using T = TrainingSetConfig;
  static const std::vector<Field<T>> fields{
      {.key = "recordings_per_pair",
       .member = &T::recordings_per_pair,
       .worlds = Worlds::problem_files,
       .elsewhere = kFitsPerFold},
      {.key = "objects",
       .member = &T::objects,
       .worlds = Worlds::problem_files,
       .elsewhere = kFitsPerFold},
      {.key = "actions",
       .member = &T::actions,
       .worlds = Worlds::problem_files,
       .elsewhere = kFitsPerFold},
      {.key = "recordings",
       .member = &T::recordings,
       .worlds = Worlds::problem_files,
       .text = Text::path,
       .elsewhere = kFitsPerFold},
      {.key = "model",
       .member = &T::model,
       .identity = Identity::file_hash,
       .worlds = Worlds::problem_files,
       .text = Text::path,
       .elsewhere = kFitsPerFold},
      {.key = "classifier", .member = &T::classifier},
      // The campaign trains with the reject option, whose `unknown` the shrunk table has no place
      // for (perception::check_fit_options): counts or soft.
      {.key = "table",
       .member = &T::table,
       .worlds = Worlds::problem_files,
       .choices =
           [] {
             return std::vector<std::string>{"counts", "soft"};
           },
       .elsewhere = kFitsPerFold},
      {.key = "catalogue",
       .member = &T::catalogue,
       .identity = Identity::file_hash,
       .worlds = Worlds::problem_files,
       .text = Text::path,
       .elsewhere = kFitsPerFold},
      {.key = "sim_config",
       .member = &T::sim_config,
       .identity = Identity::file_hash,
       .worlds = Worlds::problem_files,
       .text = Text::path,
       .elsewhere = kFitsPerFold},
  };
  return fields;
}

const std::vector<Field<ObjectGroup>>& group_fields() {
  static const std::vector<Field<ObjectGroup>> fields{
      {.key = "object", .member = &ObjectGroup::object, .required = true},
      {.key = "plays", .member = &ObjectGroup::plays},
      {.key = "trials", .member = &ObjectGroup::trials, .min = 1},
  };
  return fields;
}

const std::vector<Field<PlannerConfig>>& planner_fields() {
  static const std::vector<Field<PlannerConfig>> fields{
      // The online solvers: a campaign plans within each trial's time, not from a stored policy.
      {.key = "solver", .member = &PlannerConfig::solver, .choices = solvers::solver_names},
      {.key = "episodes", .member = &PlannerConfig::episodes},
      {.key = "step_ms", .member = &PlannerConfig::step_ms},
      {.key = "max_steps", .member = &PlannerConfig::max_steps, .min = 1},
      // Left out of the identity at its default: campaigns written before it existed.
      {.key = "self_play_trials",
       .member = &PlannerConfig::self_play_trials,
       .identity = Identity::unless_default,
       .min = 2},
  };
  return fields;
}

const std::vector<Field<CampaignConfig>>& top_fields() {
  static const std::vector<Field<CampaignConfig>> fields{
      {.key = "seed", .member = &CampaignConfig::seed},
  };
  return fields;
}

// The sections of a campaign file, in the order the JSON and identity list them.
const std::vector<std::string> kSections{"seed",         "arms",   "world",   "task",
                                         "training_set", "trials", "planner", "reference"};

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

perception::ObservationKind CampaignArm::observation_kind() const {
  return perception::parse_observation_kind(observations);
}

namespace {

// The campaign's sections as JSON, each section by `write(fields, value)`: the one shape of
// campaign.json's configuration and of the identity.
template <class Write>
nlohmann::json campaign_json(const CampaignConfig& c, Write&& write) {
  const bool recorded = c.world.recorded_data();
  nlohmann::json j = write(top_fields(), c);
  j["arms"] = nlohmann::json::array();
  for (const CampaignArm& arm : c.arms) j["arms"].push_back(write(arm_fields(), arm));
  j["world"] = write(world_fields(), c.world);
  j["world"]["type"] = to_string(c.world.type);
  // Only when given: campaigns written before noise existed keep their identities.
  if (c.world.noise.given()) j["world"]["noise"] = write(noise_fields(), c.world.noise);
  if (recorded) {
    j["task"] = write(task_fields(), c.task);
    j["task"]["rewards"] = write(reward_fields(), c.task);
    // Only when given: campaigns written before prerequisites existed keep their identities.
    if (!c.task.prerequisites.empty()) j["task"]["requires"] = c.task.prerequisites;
  }
  j["training_set"] = write(training_fields(), c.training);
  if (c.training.noise.given())
    j["training_set"]["noise"] = write(noise_fields(), c.training.noise);
  // Only when given: campaigns written before surfaces existed keep their identities.
  if (!c.world.surfaces.empty()) j["world"]["surface"] = c.world.surfaces;
  if (!c.training.surfaces.empty()) j["training_set"]["surfaces"] = c.training.surfaces;
  j["trials"] = nlohmann::json::array();  // a dataset world's file has none (the data has them)
  for (const ObjectGroup& g : c.groups) j["trials"].push_back(write(group_fields(), g));
  j["planner"] = write(planner_fields(), c.planner);
  return j;
}

}  // namespace

nlohmann::json CampaignConfig::identity() const {
  InputFiles files({}, world.series);
  return identity(files, groups);
}

nlohmann::json CampaignConfig::identity(InputFiles& files,
                                        const std::vector<ObjectGroup>& trial_groups) const {
  const config_fields::Fingerprints fingerprints{
      [&](const std::string& path) { return path.empty() ? "" : files.fingerprint(path); },
      [&](const std::string& folder) { return files.data_fingerprint(folder); }};
  // The arms as they run, in the file's words: a default that changes what an arm does changes
  // the identity, and a file that spells a default out is the same campaign as one that does not.
  CampaignConfig as_run = *this;
  as_run.groups = trial_groups;
  as_run.arms.clear();
  for (const ResolvedArm& arm : resolve_arms(*this)) as_run.arms.push_back(as_written(arm));
  nlohmann::json j = campaign_json(as_run, [&](const auto& fields, const auto& value) {
    return config_fields::write_identity(fields, value, world.recorded_data(), fingerprints);
  });
  // Without trial groups (a configuration's before its dataset world is opened) it lists none.
  if (j["trials"].empty()) j.erase("trials");
  return j;
}

nlohmann::json to_json(const CampaignConfig& c) {
  nlohmann::json j = campaign_json(c, [&](const auto& fields, const auto& value) {
    return config_fields::write_json(fields, value, c.world.recorded_data());
  });
  j["source"] = c.source;
  if (c.reference) j["reference"] = to_json(*c.reference);
  return j;
}

namespace {

// `arms`: a non-empty list with distinct names.
std::vector<CampaignArm> read_arms(const YamlReader& f, const YAML::Node& root,
                                   const config_fields::Place& at) {
  const YAML::Node arms = f.require(root, "arms", "the campaign");
  if (!arms.IsSequence() || arms.size() == 0) f.fail(arms, "arms must be a non-empty list");
  std::vector<CampaignArm> read;
  // Each arm's keys and values; what they may be together is campaign_arms.h's to say.
  for (const YAML::Node& a : arms) {
    CampaignArm arm;
    config_fields::read_yaml(f, a, arm_fields(), at, arm);
    arm.line = YamlReader::line_of(a);
    for (const CampaignArm& other : read)
      if (other.name == arm.name) f.fail(a, "two arms are named '" + arm.name + "'");
    read.push_back(std::move(arm));
  }
  return read;
}

// A noise section: its keys, each source a built-in name or a path (relative to the campaign file)
// that exists, and a ratio parse_ebr reads.
NoiseConfig read_noise(const YamlReader& f, const YAML::Node& n, const config_fields::Place& at) {
  f.expect_map(n, at.section);
  NoiseConfig noise;
  config_fields::read_yaml(f, n, noise_fields(), at, noise);
  const auto& builtins = sim::builtin_noise_names();
  for (std::string& s : noise.sources) {
    if (std::find(builtins.begin(), builtins.end(), s) != builtins.end()) continue;
    s = config_fields::resolve(at.source, s);
    std::error_code error;
    if (!fs::exists(s, error))
      f.fail(n, fmt::format("{}: source '{}' is neither built-in ({}) nor a file or folder",
                            at.section, s, fmt::join(builtins, ", ")));
  }
  if (!noise.ebr_db.empty()) try {
      sim::parse_ebr(noise.ebr_db);
    } catch (const InputError& e) {
      f.fail(n, at.section + ": " + e.problem());
    }
  if (noise.talkers < 1 || noise.talkers > sim::BackgroundNoise::kMostTalkers)
    f.fail(n, fmt::format("{}: talkers must be 1 to {} (people heard at once), not {}", at.section,
                          sim::BackgroundNoise::kMostTalkers, noise.talkers));
  return noise;
}

// Tables by name: one, or a list (which the catalogue has is checked when the world opens it).
std::vector<std::string> read_surfaces(const YamlReader& f, const YAML::Node& n,
                                       const std::string& what) {
  return n.IsSequence() ? f.names(n, what) : std::vector<std::string>{f.name(n, what)};
}

WorldConfig read_world(const YamlReader& f, const YAML::Node& root, const std::string& source) {
  const YAML::Node world = f.require(root, "world", "the campaign");
  f.expect_map(world, "world");
  WorldConfig w;
  const YAML::Node type = f.require(world, "type", "world");
  try {
    w.type = world_kind(f.name(type, "world type")).type;
  } catch (const InputError& e) {
    f.fail(type, e.problem());
  }
  config_fields::read_yaml(f, world, world_fields(), {source, "world", w.recorded_data()}, w,
                           {"type", "noise", "surface"});
  if (const YAML::Node n = f.optional(world, "surface", "world")) {
    if (w.type != WorldType::simulated)
      f.fail(n, "surface: the table a simulated world's robot acts on");
    w.surfaces = read_surfaces(f, n, "world.surface");
    w.surface_line = YamlReader::line_of(n);
  }
  if (const YAML::Node n = f.optional(world, "noise", "world")) {
    if (w.type == WorldType::model)
      f.fail(n,
             "noise: a model world hears no recordings (a simulated world or a dataset world "
             "over a recordings tree does)");
    if (!w.model.empty())
      f.fail(n,
             "noise: a dataset world with a frozen model (world.model) replays its data as it is; "
             "write a noisy copy with `echoplan add-noise` and give that as world.data");
    w.noise = read_noise(f, n, {source, "world.noise", false});
    if (w.noise.ebr_db.empty()) f.fail(n, "world.noise needs ebr_db: the ratio of each recording");
  }
  if (w.hold_out == perception::HoldOut::object && w.groups.empty())
    f.fail(world, "hold_out: object needs groups: a novel object can only be sorted by its group");
  return w;
}

// `task.requires: {BEHAVIOUR: [BEHAVIOUR, ...]}`: what each behaviour needs performed first. Which
// behaviours the data has, and whether the requirements go round in a circle, is known only once
// it is read (loop::dataset_problem checks them then); here, the shape and a behaviour naming
// itself.
std::map<std::string, std::vector<std::string>> read_requires(const YamlReader& f,
                                                              const YAML::Node& n) {
  f.expect_map(n, "task.requires");
  std::map<std::string, std::vector<std::string>> prerequisites;
  for (auto it = n.begin(); it != n.end(); ++it) {
    const std::string behaviour = f.name(it->first, "task.requires");
    const YAML::Node first = it->second;  // a copy: the iterator's pair is a temporary
    if (!first.IsSequence())
      f.fail(first, "task.requires." + behaviour + " must be a list of behaviours");
    prerequisites[behaviour] = f.names(first, "task.requires." + behaviour);
    for (std::size_t i = 0; i < first.size(); ++i)
      if (prerequisites[behaviour][i] == behaviour)
        f.fail(first[i], behaviour + " cannot require itself");
  }
  return prerequisites;
}

// `task: {rewards: {right, wrong, sense}, costs: {BEHAVIOUR: C}, requires: {BEHAVIOUR: [...]}}`, a
// dataset world's task (one key at least; the others keep their defaults).
loop::TaskSpec read_task(const YamlReader& f, const YAML::Node& task,
                         const config_fields::Place& at) {
  loop::TaskSpec spec;
  config_fields::read_yaml(f, task, task_fields(), {at.source, "task", true}, spec,
                           {"rewards", "requires"});
  if (const YAML::Node n = f.optional(task, "requires", "task"))
    spec.prerequisites = read_requires(f, n);
  const YAML::Node r = f.optional(task, "rewards", "task");
  if (!r) {
    if (spec.costs.empty() && spec.prerequisites.empty())
      f.fail(task, "task: give rewards, costs, requires or some of them");
    return spec;
  }
  config_fields::read_yaml(f, r, reward_fields(), {at.source, "task.rewards", true}, spec);
  if (!(spec.right > spec.wrong)) f.fail(r, "task.rewards: right must be greater than wrong");
  return spec;
}

// How the classifier is trained (or the trained model used instead): the `training_set` mapping.
TrainingSetConfig read_training_set(const YamlReader& f, const YAML::Node& t,
                                    const config_fields::Place& at, bool frozen_model) {
  if (frozen_model)
    f.fail(t, "training_set: the world's model is frozen (world.model); nothing is trained");
  TrainingSetConfig training;
  config_fields::read_yaml(f, t, training_fields(), at, training, {"noise", "surfaces"});
  if (const YAML::Node n = f.optional(t, "surfaces", "training_set")) {
    if (at.recorded_data) f.fail(n, std::string("surfaces: ") + kFitsPerFold);
    training.surfaces = read_surfaces(f, n, "training_set.surfaces");
    training.surfaces_line = YamlReader::line_of(n);
  }
  if (const YAML::Node n = f.optional(t, "noise", "training_set")) {
    training.noise = read_noise(f, n, {at.source, "training_set.noise", false});
  }
  // Keys that say how this campaign trains mean nothing next to a trained model: an error, not
  // a silently ignored setting.
  if (!training.model.empty())
    for (const char* key : {"classifier", "table"})
      if (auto n = f.optional(t, key, "training_set"))
        f.fail(n, fmt::format("{} chooses how this campaign trains; with model: the model file "
                              "has its own",
                              key));
  return training;
}

std::vector<ObjectGroup> read_trial_groups(const YamlReader& f, const YAML::Node& trials,
                                           const config_fields::Place& at) {
  if (!trials.IsSequence() || trials.size() == 0)
    f.fail(trials, "trials must be a non-empty list of object groups");
  std::vector<ObjectGroup> groups;
  for (const YAML::Node& g : trials) {
    ObjectGroup group;
    config_fields::read_yaml(f, g, group_fields(), at, group);
    if (group.plays.empty()) group.plays = group.object;
    for (const ObjectGroup& other : groups)
      if (other.object == group.object)
        f.fail(g, "object '" + group.object + "' has two trial groups");
    groups.push_back(group);
  }
  return groups;
}

PlannerConfig read_planner(const YamlReader& f, const YAML::Node& root,
                           const config_fields::Place& at) {
  const YAML::Node p = f.optional(root, "planner", "campaign");
  if (!p) f.fail(root, "missing key 'planner' (its budget: episodes or step_ms)");
  PlannerConfig planner;
  config_fields::read_yaml(f, p, planner_fields(), at, planner);
  if ((planner.episodes > 0) == (planner.step_ms > 0))
    f.fail(p, "give exactly one planning budget: episodes (reproducible) or step_ms");
  return planner;
}

// The reference file named by `reference:`, read whole (its mistakes name its own lines).
std::optional<ReferenceResults> read_reference(const YamlReader& f, const YAML::Node& root,
                                               const std::string& source) {
  const YAML::Node n = f.optional(root, "reference", "campaign");
  if (!n) return std::nullopt;
  const std::string path = config_fields::resolve(source, f.name(n, "reference"));
  std::error_code error;
  if (!fs::is_regular_file(path, error)) f.fail(n, "reference file '" + path + "' does not exist");
  return load_reference_results(path);
}

// The sections that only one kind of world takes: a dataset world's trials are its data's
// sessions, and a problem file gives a model or simulated world's rewards.
void read_world_sections(const YamlReader& f, const YAML::Node& root, CampaignConfig& c) {
  const config_fields::Place at{c.source, "the campaign", c.world.recorded_data()};
  if (c.world.recorded_data()) {
    if (auto t = f.optional(root, "trials", "campaign"))
      f.fail(t, "a dataset world's trials are the data's (object, session) pairs: remove trials");
    if (auto t = f.optional(root, "task", "campaign")) c.task = read_task(f, t, at);
    return;
  }
  c.groups = read_trial_groups(f, f.require(root, "trials", "the campaign"),
                               {c.source, "a trial group", false});
  if (auto t = f.optional(root, "task", "campaign"))
    f.fail(t,
           "task is for dataset worlds; the problem file gives a model or simulated world's "
           "rewards");
}

CampaignConfig read_campaign(const std::string& yaml_text, const std::string& source) {
  const YamlReader f(source);
  const YAML::Node root = parse_yaml(yaml_text, source);
  f.expect_map(root, "the campaign");
  f.reject_duplicate_keys(root);
  f.only_keys(root, kSections, "the campaign");

  CampaignConfig c;
  c.source = source;
  c.world = read_world(f, root, source);
  const bool recorded = c.world.recorded_data();
  for (const Field<CampaignConfig>& field : top_fields())
    config_fields::read_yaml_field(f, root, field, {source, "the campaign", recorded}, c);
  c.arms = read_arms(f, root, {source, "an arm", recorded});
  if (auto t = f.optional(root, "training_set", "campaign"))
    c.training =
        read_training_set(f, t, {source, "training_set", recorded}, !c.world.model.empty());
  read_world_sections(f, root, c);
  c.planner = read_planner(f, root, {source, "planner", recorded});
  c.reference = read_reference(f, root, source);
  return c;
}

}  // namespace

CampaignConfig parse_campaign_config(const std::string& yaml_text, const std::string& source) {
  return read_yaml_guarded(source, [&] { return read_campaign(yaml_text, source); });
}

CampaignConfig load_campaign_config(const std::string& path) {
  return parse_campaign_config(read_text_file(path, "campaign file"), path);
}

namespace {

namespace jf = json_fields;

// Reads a list section (arms, trials) written by campaign_json.
template <class T>
std::vector<T> list_from_json(const nlohmann::json& j, const char* key,
                              const std::vector<Field<T>>& fields, const jf::JsonSource& source,
                              bool recorded) {
  std::vector<T> list;
  const nlohmann::json& items = jf::array(jf::member(j, key, "", source), key, source);
  for (std::size_t i = 0; i < items.size(); ++i) {
    T item;
    config_fields::read_json(items[i], fields, jf::element(key, i), source, recorded, item);
    list.push_back(std::move(item));
  }
  return list;
}

WorldType world_type_from_json(const nlohmann::json& j, const jf::JsonSource& source) {
  const nlohmann::json& w = jf::member(j, "world", "", source);
  const std::string type = jf::string(jf::member(w, "type", "world", source), "world.type", source);
  try {
    return world_kind(type).type;
  } catch (const InputError& e) {
    throw InputError(source.file, source.line, "world.type: " + e.problem());
  }
}

}  // namespace

CampaignConfig campaign_config_from_json(const nlohmann::json& j, const std::string& source) {
  const jf::JsonSource from(source);
  CampaignConfig c;
  c.source = jf::string(jf::member(j, "source", "", from), "source", from);
  c.world.type = world_type_from_json(j, from);
  const bool recorded = c.world.recorded_data();
  const auto section = [&](const char* key) -> const nlohmann::json& {
    return jf::member(j, key, "", from);
  };
  config_fields::read_json(j, top_fields(), "", from, recorded, c);
  c.arms = list_from_json(j, "arms", arm_fields(), from, recorded);
  config_fields::read_json(section("world"), world_fields(), "world", from, recorded, c.world);
  if (const nlohmann::json* n = jf::optional_member(section("world"), "noise", "world", from))
    config_fields::read_json(*n, noise_fields(), "world.noise", from, recorded, c.world.noise);
  if (const nlohmann::json* n = jf::optional_member(section("world"), "surface", "world", from))
    c.world.surfaces = jf::strings(*n, "world.surface", from);
  if (const nlohmann::json* task = jf::optional_member(j, "task", "", from)) {
    config_fields::read_json(*task, task_fields(), "task", from, recorded, c.task);
    config_fields::read_json(jf::member(*task, "rewards", "task", from), reward_fields(),
                             "task.rewards", from, recorded, c.task);
    if (const nlohmann::json* n = jf::optional_member(*task, "requires", "task", from)) {
      if (!n->is_object())
        throw InputError(from.file, from.line, "task.requires must be an object");
      for (const auto& [behaviour, first] : n->items())
        c.task.prerequisites[behaviour] = jf::strings(first, "task.requires." + behaviour, from);
    }
  }
  config_fields::read_json(section("training_set"), training_fields(), "training_set", from,
                           recorded, c.training);
  if (const nlohmann::json* n =
          jf::optional_member(section("training_set"), "noise", "training_set", from))
    config_fields::read_json(*n, noise_fields(), "training_set.noise", from, recorded,
                             c.training.noise);
  if (const nlohmann::json* n =
          jf::optional_member(section("training_set"), "surfaces", "training_set", from))
    c.training.surfaces = jf::strings(*n, "training_set.surfaces", from);
  c.groups = list_from_json(j, "trials", group_fields(), from, recorded);
  config_fields::read_json(section("planner"), planner_fields(), "planner", from, recorded,
                           c.planner);
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
