#include "experiment/campaign.h"

#include <fmt/format.h>

#include <algorithm>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "common/error.h"
#include "common/rng.h"
#include "experiment/calibrated_problem.h"
#include "experiment/campaign_figures.h"
#include "experiment/environment_factory.h"
#include "experiment/html_report.h"
#include "perception/recording_set.h"
#include "pomdp/model_environment.h"
#include "pomdp/problem.h"
#include "sim/catalogue.h"
#include "sim/dataset.h"
#include "sim/sim_config.h"

namespace echoplan::experiment {

namespace {

namespace fs = std::filesystem;

constexpr const char* kJournal = "journal.jsonl";
constexpr const char* kDescription = "campaign.json";

void write_text(const fs::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::trunc | std::ios::binary);
  out << text;
  if (!out) throw InputError(path.string(), 0, "cannot write");
}

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path.string(), 0, "cannot open");
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

nlohmann::json description(const CampaignConfig& config) {
  return {{"config", to_json(config)}, {"identity", config.identity()}};
}

// The names a problem shares with the other arms: objects, actions, heard classes.
std::string names_of(const pomdp::ModelSpec& spec) {
  std::string text = "objects";
  for (const auto& o : spec.state.discrete_value_names.at(0)) text += " " + o;
  text += "; actions";
  for (const auto& a : spec.action_names) text += " " + a;
  text += "; observations";
  for (const auto& o : spec.observation.names) text += " " + o;
  return text;
}

// The output folder exists and takes files.
void check_writable(const fs::path& directory) {
  std::error_code error;
  fs::create_directories(directory, error);
  if (error)
    throw InputError(directory.string(), 0, "cannot create the output folder: " + error.message());
  const fs::path probe = directory / ".echoplan-write-test";
  {
    std::ofstream out(probe);
    out << "probe\n";
    if (!out) throw InputError(directory.string(), 0, "the output folder cannot be written");
  }
  fs::remove(probe, error);
}

// The object-identification data of a loaded problem (calibration replaces its table).
const pomdp::ObjectProblemData& object_data(const pomdp::Problem& problem) {
  const auto* model = dynamic_cast<const pomdp::ObjectIdentificationModel*>(problem.model.get());
  if (!model)
    throw InputError(problem.source_path, 0,
                     "an arm that calibrates needs an object-identification problem");
  return model->data();
}

sim::Catalogue campaign_catalogue(const CampaignConfig& config) {
  return sim::load_catalogue(config.training.catalogue.empty() ? sim::default_catalogue_path()
                                                               : config.training.catalogue);
}

sim::SimConfig campaign_sim_config(const CampaignConfig& config) {
  return config.training.sim_config.empty() ? sim::SimConfig{}
                                            : sim::load_sim_config(config.training.sim_config);
}

// The closed-loop settings of the world for trials of `group`.
LoopSettings loop_settings(const CampaignConfig& config,
                           std::shared_ptr<const perception::ObservationModel> model,
                           const ObjectGroup& group) {
  LoopSettings settings;
  settings.model = pomdp::load_problem(config.world.problem).model;
  settings.world.kind = WorldSettings::Kind::simulator;
  settings.world.catalogue = campaign_catalogue(config);
  settings.world.config = campaign_sim_config(config);
  settings.classifier = std::move(model);
  if (group.object != group.plays) settings.world_objects[group.plays] = group.object;
  return settings;
}

// Checks that `model` fits the campaign (calibrating arms and a simulated world); InputError if
// not.
void check_classifier(const CampaignConfig& config,
                      const std::shared_ptr<const perception::ObservationModel>& model) {
  for (const CampaignArm& arm : config.arms)
    if (arm.calibrate) calibrated_problem(object_data(pomdp::load_problem(arm.problem)), *model);
  if (config.world.type == "simulated")
    for (const ObjectGroup& group : config.groups)
      make_environment_factory(loop_settings(config, model, group));
}

}  // namespace

bool needs_classifier(const CampaignConfig& config) {
  if (config.world.type == "simulated") return true;
  return std::any_of(config.arms.begin(), config.arms.end(),
                     [](const CampaignArm& a) { return a.calibrate; });
}

Campaign open_campaign(const CampaignConfig& config, const fs::path& directory) {
  Campaign c;
  c.config = config;
  c.directory = directory;

  // The problems: each loads, and all share objects, actions and observations with the world.
  std::vector<pomdp::Problem> problems;
  for (const CampaignArm& arm : config.arms) problems.push_back(pomdp::load_problem(arm.problem));
  const pomdp::Problem world = pomdp::load_problem(config.world.problem);
  const pomdp::ModelSpec& spec = world.model->spec();
  if (spec.state.discrete_value_names.empty())
    throw InputError(world.source_path, 0,
                     "a campaign needs an object-identification problem (objects as its state)");
  for (const pomdp::Problem& p : problems)
    if (names_of(p.model->spec()) != names_of(spec))
      throw InputError(
          p.source_path, 0,
          fmt::format(
              "the arms and the world must share objects, actions and observations: this file "
              "has {}, the world's {} has {}",
              names_of(p.model->spec()), world.source_path, names_of(spec)));
  c.results.spec = spec;
  c.results.config = config;
  c.results.planned_trials = config.total_trials();
  c.results.belief_particles = problems.front().belief.type == pomdp::BeliefSettings::Type::particle
                                   ? problems.front().belief.particles
                                   : 0;
  for (const pomdp::Problem& p : problems)
    if ((p.belief.type == pomdp::BeliefSettings::Type::particle ? p.belief.particles : 0) !=
        c.results.belief_particles)
      c.results.belief_particles = 0;  // arms disagree: show probabilities

  // Every solver can be built (unknown names and bad settings fail now, not in a worker).
  for (const pomdp::Problem& p : problems) make_arm_planner(config, p);

  // Objects: each group plays an object of the problems, and every object named has a catalogue
  // entry.
  const auto& objects = spec.state.discrete_value_names[0];
  for (const ObjectGroup& g : config.groups)
    if (std::find(objects.begin(), objects.end(), g.plays) == objects.end())
      throw InputError(config.source, 0,
                       fmt::format("trial group '{}' plays '{}', which is not an object of {}",
                                   g.object, g.plays, world.source_path));
  const sim::Catalogue catalogue =
      sim::load_catalogue(config.training.catalogue.empty() ? sim::default_catalogue_path()
                                                            : config.training.catalogue);
  c.training_objects = config.training.objects.empty() ? objects : config.training.objects;
  c.training_actions = config.training.actions;
  // By default the problems' sound-making actions the simulator can perform.
  if (c.training_actions.empty())
    for (const auto& a : spec.action_names)
      if (a == "slide" || a == "strike") c.training_actions.push_back(a);
  std::vector<std::string> named = c.training_objects;
  for (const ObjectGroup& g : config.groups) named.push_back(g.object);
  for (const std::string& o : objects) named.push_back(o);
  const auto known = catalogue.object_names();
  for (const std::string& name : named)
    if (std::find(known.begin(), known.end(), name) == known.end()) {
      std::string list;
      for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
      throw InputError(config.source, 0,
                       fmt::format("object '{}' has no entry in the catalogue {} (it has: {})",
                                   name, catalogue.source, list));
    }
  if (!config.training.recordings.empty() && !fs::is_directory(config.training.recordings))
    throw InputError(config.training.recordings, 0, "the recordings folder does not exist");
  if (!config.training.sim_config.empty()) sim::load_sim_config(config.training.sim_config);
  for (const pomdp::Problem& p : problems)
    for (const CampaignArm& arm : config.arms)
      if (arm.calibrate && arm.problem == p.source_path) object_data(p);
  // A given model must be one for these objects and actions.
  if (!config.training.model.empty() && needs_classifier(config)) {
    c.observation_model = std::make_shared<const perception::ObservationModel>(
        perception::load_observation_model(config.training.model));
    check_classifier(config, c.observation_model);
  } else if (needs_classifier(config) && config.training.recordings_per_pair == 0 &&
             config.training.recordings.empty()) {
    throw InputError(
        config.source, 0,
        "a calibrating arm or a simulated world needs a classifier: give training_set.model, "
        "training_set.recordings or recordings_per_pair > 0");
  }
  c.planning = config;

  // The output folder: writable, and either new or holding this same campaign.
  check_writable(directory);
  const fs::path described = directory / kDescription;
  const nlohmann::json mine = description(config);
  if (fs::exists(described)) {
    const nlohmann::json theirs = nlohmann::json::parse(read_text(described), nullptr, false);
    if (theirs.is_discarded() || !theirs.contains("identity") ||
        theirs["identity"] != mine["identity"])
      throw InputError(
          directory.string(), 0,
          "holds a different campaign (its campaign.json differs from this configuration); "
          "choose another --out, or remove the folder to start again");
  }
  write_text(described, mine.dump(2) + "\n");
  return c;
}

fs::path training_recordings(const Campaign& campaign) {
  if (!campaign.config.training.recordings.empty()) return campaign.config.training.recordings;
  return campaign.directory / "training" / "recordings";
}

namespace {

// Synthesises the training set unless complete already; false when stopped.
bool synthesise(const Campaign& campaign, const perception::ProgressFn& progress,
                const std::atomic<bool>& stop) {
  const CampaignConfig& config = campaign.config;
  if (!config.training.recordings.empty() || config.training.recordings_per_pair == 0) return true;
  const fs::path folder = training_recordings(campaign);
  const int total =
      config.training.recordings_per_pair *
      static_cast<int>(campaign.training_objects.size() * campaign.training_actions.size());
  // Complete already (a resumed run): the manifest lists every clip.
  {
    std::ifstream manifest(folder / "manifest.csv");
    int rows = -1;  // the header
    std::string line;
    while (std::getline(manifest, line)) ++rows;
    if (rows == total) return true;
  }
  sim::DatasetOptions options;
  options.objects = campaign.training_objects;
  options.actions = campaign.training_actions;
  options.per_pair = config.training.recordings_per_pair;
  options.seed =
      derive_seed(config.seed, {0x747261696eull});  // "train": the training set's own stream
  options.output_dir = folder.string();
  const sim::DatasetSummary summary = sim::write_dataset(
      campaign_catalogue(config), campaign_sim_config(config), options,
      [&](int done, int all, const std::string&) {
        if (progress) progress("synthesise", done, all);
      },
      stop);
  return !summary.interrupted;
}

}  // namespace

bool prepare_training(Campaign& campaign, const perception::ProgressFn& progress,
                      const std::atomic<bool>& stop) {
  if (!synthesise(campaign, progress, stop)) return false;
  const CampaignConfig& config = campaign.config;
  campaign.planning = config;
  if (!needs_classifier(config)) return true;
  const fs::path training = campaign.directory / "training";
  fs::create_directories(training);
  if (!campaign.observation_model) {
    const fs::path saved = training / "model.json";
    if (fs::exists(saved)) {
      campaign.observation_model = std::make_shared<const perception::ObservationModel>(
          perception::load_observation_model(saved.string()));
    } else {
      perception::TrainOptions options;
      if (!config.training.classifier.empty()) options.classifier = config.training.classifier;
      if (!config.training.table.empty())
        options.table = perception::parse_table_estimate(config.training.table);
      // Both arms must hear the same symbols to be compared trial by trial: no reject option.
      options.reject = false;
      options.seed = derive_seed(config.seed, {0x63616c6962ull});  // "calib": fold assignment
      perception::ObservationModel model = perception::train_observation_model(
          perception::load_recording_set(training_recordings(campaign).string()), options,
          progress);
      if (stop) return false;
      // Written under a temporary name, then renamed: a model.json on disk is always whole.
      const fs::path temporary = training / "model.json.tmp";
      perception::save_observation_model(model, temporary.string());
      fs::rename(temporary, saved);
      campaign.observation_model =
          std::make_shared<const perception::ObservationModel>(std::move(model));
    }
    check_classifier(config, campaign.observation_model);
  }
  for (CampaignArm& arm : campaign.planning.arms) {
    if (!arm.calibrate) continue;
    const pomdp::Problem base = pomdp::load_problem(arm.problem);
    const pomdp::ObjectProblemData data =
        calibrated_problem(object_data(base), *campaign.observation_model);
    const fs::path file = training / (arm.name + ".problem.yaml");
    std::ostringstream text;
    pomdp::write_problem_yaml(text, data, base.belief, base.planner);
    write_text(file, text.str());
    arm.problem = file.string();
    // The world reports symbols by the world problem's indices; the arm must read them the same
    // way.
    const pomdp::Problem calibrated = pomdp::load_problem(arm.problem);
    const pomdp::Problem world = pomdp::load_problem(config.world.problem);
    if (names_of(calibrated.model->spec()) != names_of(world.model->spec()))
      throw InputError(
          arm.problem, 0,
          fmt::format(
              "the calibrated problem has {}, the world's {} has {}: train on the problem's "
              "objects in its order",
              names_of(calibrated.model->spec()), world.source_path,
              names_of(world.model->spec())));
  }
  return true;
}

WorldFactory make_world(const Campaign& campaign) {
  if (campaign.config.world.type == "simulated") {
    if (!campaign.observation_model)
      throw std::logic_error("make_world: call prepare_training() first");
    const CampaignConfig config = campaign.config;
    const auto model = campaign.observation_model;
    return [config, model](const ObjectGroup& group) -> std::unique_ptr<pomdp::Environment> {
      return make_environment_factory(loop_settings(config, model, group))();
    };
  }
  const std::string problem = campaign.config.world.problem;
  // The model as the world: each worker loads its own copy, so no state is shared between threads.
  return [problem](const ObjectGroup&) -> std::unique_ptr<pomdp::Environment> {
    return std::make_unique<pomdp::ModelEnvironment>(pomdp::load_problem(problem).model);
  };
}

std::vector<TrialJob> remaining_jobs(const Campaign& campaign, const Shard& shard) {
  std::set<int> done;
  for (const JournalEntry& e : read_journal(campaign.directory / kJournal)) done.insert(e.id);
  std::vector<TrialJob> jobs;
  for (const TrialJob& job : campaign_jobs(campaign.config))
    if (shard.contains(job.id) && !done.count(job.id)) jobs.push_back(job);
  return jobs;
}

std::string rebuild_report(const Campaign& campaign, bool figures) {
  const fs::path& dir = campaign.directory;
  std::vector<JournalEntry> entries = read_journal(dir / kJournal);
  // One entry per id (a trial journalled twice by overlapping runs is the same trial), in id order.
  std::map<int, JournalEntry> by_id;
  for (JournalEntry& e : entries) by_id.emplace(e.id, std::move(e));
  entries.clear();
  for (auto& [id, e] : by_id) entries.push_back(std::move(e));
  write_journal(dir / kJournal, entries);

  CampaignResults results = campaign.results;
  results.entries = std::move(entries);
  write_tables(dir, results);
  write_text(dir / "summary.json", summary_json(results).dump(2) + "\n");
  const std::string text = summary_text(results);
  write_text(dir / "summary.txt", text);
  if (figures) {
    const std::vector<TemplateMatrix> templates = template_matrices(
        training_recordings(campaign), campaign.training_objects, campaign.training_actions);
    const std::vector<Figure> drawn = draw_figures(dir, results, templates);
    write_text(dir / "index.html", html_report(dir, results, drawn));
  }
  return text;
}

std::string merge_campaigns(const fs::path& directory, const std::vector<fs::path>& shards) {
  if (shards.empty()) throw InputError("merge: name at least one shard folder");
  nlohmann::json first;
  for (const fs::path& shard : shards) {
    const fs::path described = shard / kDescription;
    if (!fs::exists(described))
      throw InputError(shard.string(), 0, "is not a campaign folder (no campaign.json)");
    const nlohmann::json j = nlohmann::json::parse(read_text(described), nullptr, false);
    if (j.is_discarded() || !j.contains("identity") || !j.contains("config"))
      throw InputError(described.string(), 0, "is not a campaign description");
    if (first.is_null())
      first = j;
    else if (j["identity"] != first["identity"])
      throw InputError(shard.string(), 0,
                       fmt::format("holds another campaign than {} (their campaign.json differ)",
                                   shards[0].string()));
  }
  for (const fs::path& shard : shards)
    if (fs::exists(directory) && fs::equivalent(shard, directory))
      throw InputError(directory.string(), 0, "the merged folder must not be one of the shards");
  const CampaignConfig config =
      campaign_config_from_json(first["config"], (shards[0] / kDescription).string());
  const Campaign campaign = open_campaign(config, directory);

  // The training set of the first shard that has one (every shard synthesised the same one).
  if (config.training.recordings.empty())
    for (const fs::path& shard : shards) {
      const fs::path source = shard / "training";
      if (!fs::is_directory(source)) continue;
      std::error_code error;
      fs::remove_all(directory / "training", error);
      fs::copy(source, directory / "training", fs::copy_options::recursive, error);
      if (error)
        throw InputError((directory / "training").string(), 0,
                         "cannot copy the training set: " + error.message());
      break;
    }

  std::map<int, JournalEntry> by_id;
  for (const fs::path& shard : shards)
    for (JournalEntry& e : read_journal(shard / kJournal)) {
      auto [it, inserted] = by_id.emplace(e.id, e);
      if (!inserted && !(it->second == e))
        throw InputError(
            (shard / kJournal).string(), 0,
            fmt::format("trial {} differs from the same trial in another shard", e.id));
    }
  for (JournalEntry& e : read_journal(directory / kJournal)) by_id.emplace(e.id, std::move(e));
  std::vector<JournalEntry> entries;
  for (auto& [id, e] : by_id) entries.push_back(std::move(e));
  write_journal(directory / kJournal, entries);
  return rebuild_report(campaign);
}

}  // namespace echoplan::experiment
