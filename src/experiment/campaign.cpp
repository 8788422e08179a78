#include "experiment/campaign.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "common/error.h"
#include "common/file_io.h"
#include "experiment/campaign_figures.h"
#include "experiment/html_report.h"
#include "loop/calibrated_problem.h"
#include "loop/loop.h"
#include "loop/object_problem.h"
#include "loop/prepare_observation.h"
#include "loop/streams.h"
#include "perception/heard_confusion.h"
#include "pomdp/problem.h"
#include "sim/sound_action.h"

namespace echoplan::experiment {

namespace {

namespace fs = std::filesystem;

constexpr const char* kJournal = "journal.jsonl";
constexpr const char* kDescription = "campaign.json";

// The campaign's input files, each read once: parsed from the same text its fingerprint in the
// campaign's identity is taken from.
class InputFiles {
 public:
  const std::string& text(const std::string& path) {
    auto it = texts_.find(path);
    if (it == texts_.end()) it = texts_.emplace(path, read_text_file(path, "file")).first;
    return it->second;
  }
  std::shared_ptr<const pomdp::Problem> problem(const std::string& path) {
    auto it = problems_.find(path);
    if (it == problems_.end())
      it = problems_
               .emplace(path, std::make_shared<const pomdp::Problem>(
                                  pomdp::parse_problem(text(path), path)))
               .first;
    return it->second;
  }

 private:
  std::map<std::string, std::string> texts_;
  std::map<std::string, std::shared_ptr<const pomdp::Problem>> problems_;
};

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

// The problems: each loads, and all share objects, actions and observations with the world.
void load_problems(Campaign& c, InputFiles& files) {
  const CampaignConfig& config = c.config;
  c.world_problem = files.problem(config.world.problem);
  const pomdp::ModelSpec& spec = c.world_problem->model->spec();
  if (spec.state.discrete_value_names.empty())
    throw InputError(config.world.problem, 0,
                     "a campaign needs an object-identification problem (objects as its state)");
  for (const CampaignArm& arm : config.arms) {
    c.arm_problems.push_back(files.problem(arm.problem));
    loop::check_same_names(*c.arm_problems.back(), *c.world_problem);
    // Every solver can be built (unknown names and bad settings fail now, not in a worker).
    loop::check_planner(arm_planner(config, arm), *c.arm_problems.back());
    if (arm.calibrate) loop::object_problem(*c.arm_problems.back()->model);
  }
  c.results.spec = spec;
  c.results.config = config;
  c.results.planned_trials = config.total_trials();
  const auto particles = [](const pomdp::Problem& p) {
    return p.belief.type == pomdp::BeliefSettings::Type::particle ? p.belief.particles : 0;
  };
  c.results.belief_particles = particles(*c.arm_problems.front());
  for (const auto& p : c.arm_problems)
    if (particles(*p) != c.results.belief_particles)
      c.results.belief_particles = 0;  // arms disagree: show probabilities
}

// Objects: each group plays an object of the problems, and every object named has a catalogue
// entry. Fills the training set's objects and actions.
void check_objects(Campaign& c) {
  const CampaignConfig& config = c.config;
  const auto& objects = c.results.spec.state.discrete_value_names[0];
  for (const ObjectGroup& g : config.groups)
    if (std::find(objects.begin(), objects.end(), g.plays) == objects.end())
      throw InputError(config.source, 0,
                       fmt::format("trial group '{}' plays '{}', which is not an object of {}",
                                   g.object, g.plays, config.world.problem));
  c.training_objects = config.training.objects.empty() ? objects : config.training.objects;
  c.training_actions = config.training.actions;
  // By default the problems' sound-making actions the simulator can perform.
  if (c.training_actions.empty())
    for (const auto& a : c.results.spec.action_names)
      if (sim::find_sound_action(a)) c.training_actions.push_back(a);
  std::vector<std::string> named = c.training_objects;
  for (const ObjectGroup& g : config.groups) named.push_back(g.object);
  for (const std::string& o : objects) named.push_back(o);
  const auto known = c.catalogue->object_names();
  for (const std::string& name : named)
    if (std::find(known.begin(), known.end(), name) == known.end())
      throw InputError(config.source, 0,
                       fmt::format("object '{}' has no entry in the catalogue {} (it has: {})",
                                   name, c.catalogue->source, fmt::join(known, ", ")));
}

// The simulator's inputs: the catalogue and the sim config, loaded once.
void load_simulator(Campaign& c, InputFiles& files) {
  const TrainingSetConfig& t = c.config.training;
  const std::string catalogue = t.catalogue.empty() ? sim::default_catalogue_path() : t.catalogue;
  c.catalogue = std::make_shared<const sim::Catalogue>(
      sim::parse_catalogue(files.text(catalogue), catalogue));
  c.sim_config = std::make_shared<const sim::SimConfig>(
      t.sim_config.empty() ? sim::SimConfig{}
                           : sim::parse_sim_config(files.text(t.sim_config), t.sim_config));
}

// The folder holds this campaign or none: claims it by writing campaign.json.
void claim_folder(Campaign& c, InputFiles& files) {
  check_writable(c.directory);
  const fs::path described = c.directory / kDescription;
  c.results.identity = c.config.identity([&](const std::string& path) { return files.text(path); });
  const nlohmann::json mine = {{"config", to_json(c.config)}, {"identity", c.results.identity}};
  if (fs::exists(described)) {
    const nlohmann::json theirs = nlohmann::json::parse(
        read_text_file(described.string(), "campaign description"), nullptr, false);
    if (theirs.is_discarded() || !theirs.contains("identity") ||
        theirs["identity"] != mine["identity"])
      throw InputError(
          c.directory.string(), 0,
          "holds a different campaign (its campaign.json differs from this configuration); "
          "choose another --out, or remove the folder to start again");
  }
  write_file_atomically(described, mine.dump(2) + "\n");
}

bool simulated(const CampaignConfig& config) { return config.world.type == WorldType::simulated; }

// The checked loop of every arm and group; InputError when a part does not fit.
ArmLoops make_loops(const Campaign& c) {
  ArmLoops loops(c.config.arms.size());
  for (std::size_t a = 0; a < c.config.arms.size(); ++a)
    for (const ObjectGroup& group : c.config.groups) {
      loop::LoopSettings s;
      s.problem = c.arm_problems[a];
      s.world_problem = c.world_problem;
      if (simulated(c.config)) {
        s.world = loop::SimulatedWorldSpec{c.catalogue, c.sim_config};
        s.classifier = c.observation_model;
        if (group.object != group.plays) s.world_objects[group.plays] = group.object;
      }
      s.planner = arm_planner(c.config, c.config.arms[a]);
      s.max_steps = c.config.planner.max_steps;
      auto spec = std::make_shared<const loop::LoopSpec>(std::move(s));
      const int object = loop::object_index(spec->problem(), group.plays);
      loops[a].push_back({TrialLoop{std::move(spec), object, ""}});
    }
  return loops;
}

// A dataset world: the data and its folds instead of problem files, the simulator and trial
// groups; every arm's strategy checked against the names problem.
void open_dataset_world(Campaign& c) {
  c.dataset = std::make_shared<DatasetTrials>(open_dataset(c.config));
  c.config.groups = dataset_groups(*c.dataset);
  for (const CampaignArm& arm : c.config.arms)
    loop::check_planner(arm_planner(c.config, arm), *c.dataset->names);
  c.results.spec = c.dataset->names->model->spec();
  c.results.config = c.config;
  c.results.planned_trials = c.config.total_trials();
  c.results.right_action = right_actions(*c.dataset);
  c.results.sensing_actions = static_cast<int>(c.dataset->data->actions.size());
}

}  // namespace

bool needs_classifier(const CampaignConfig& config) {
  if (simulated(config)) return true;
  if (config.world.type == WorldType::dataset) return false;  // fitted per fold instead
  return std::any_of(config.arms.begin(), config.arms.end(),
                     [](const CampaignArm& a) { return a.calibrate; });
}

Campaign open_campaign(const CampaignConfig& config, const fs::path& directory) {
  Campaign c;
  c.config = config;
  c.directory = directory;
  InputFiles files;
  if (config.world.type == WorldType::dataset) {
    open_dataset_world(c);
    claim_folder(c, files);
    return c;
  }
  load_problems(c, files);
  load_simulator(c, files);
  check_objects(c);
  if (!config.training.recordings.empty() && !fs::is_directory(config.training.recordings))
    throw InputError(config.training.recordings, 0, "the recordings folder does not exist");
  if (!config.training.model.empty() && needs_classifier(config)) {
    // A given model must be one for these objects and actions.
    c.observation_model =
        std::make_shared<const perception::ObservationModel>(perception::parse_observation_model(
            files.text(config.training.model), config.training.model));
    for (std::size_t a = 0; a < config.arms.size(); ++a)
      if (config.arms[a].calibrate)
        loop::calibrate_problem(*c.arm_problems[a], *c.observation_model);
    make_loops(c);
  } else if (needs_classifier(config) && config.training.recordings_per_pair == 0 &&
             config.training.recordings.empty()) {
    throw InputError(
        config.source, 0,
        "a calibrating arm or a simulated world needs a classifier: give training_set.model, "
        "training_set.recordings or recordings_per_pair > 0");
  }
  claim_folder(c, files);
  return c;
}

fs::path training_recordings(const Campaign& campaign) {
  if (!campaign.config.training.recordings.empty()) return campaign.config.training.recordings;
  return campaign.directory / "training" / "recordings";
}

namespace {

// The campaign's training set as the loop synthesises it.
loop::SimulatedTraining simulated_training(const Campaign& c) {
  loop::SimulatedTraining t;
  t.catalogue = c.catalogue;
  t.config = c.sim_config;
  t.objects = c.training_objects;
  t.actions = c.training_actions;
  t.per_pair = c.config.training.recordings_per_pair;
  t.seed = loop::stream_seed(c.config.seed, loop::Stream::campaign_training);
  t.directory = training_recordings(c);
  t.reuse_complete = true;
  return t;
}

// The classifier: training_set.model (loaded already), DIR/training/model.json of an earlier run,
// or trained now on the training set (and saved there for the user). Null when stopped.
std::shared_ptr<const perception::ObservationModel> classifier(const Campaign& c,
                                                               const ProgressFn& progress,
                                                               const std::atomic<bool>& stop) {
  if (c.observation_model) return c.observation_model;
  const fs::path saved = c.directory / "training" / "model.json";
  if (fs::exists(saved))
    return loop::prepare_observation(loop::ModelFile{saved.string()}, nullptr, "", progress, stop)
        .model;
  loop::RecordingsTraining training{training_recordings(c).string(), {}, saved.string()};
  const TrainingSetConfig& config = c.config.training;
  if (!config.classifier.empty()) training.train.classifier = config.classifier;
  if (!config.table.empty()) training.train.table = perception::parse_table_estimate(config.table);
  // Both arms must hear the same symbols to be compared trial by trial: no reject option.
  training.train.reject = false;
  training.train.seed = loop::stream_seed(c.config.seed, loop::Stream::campaign_folds);
  return loop::prepare_observation(training, nullptr, "", progress, stop).model;
}

}  // namespace

bool prepare_training(Campaign& campaign, const ProgressFn& progress,
                      const std::atomic<bool>& stop) {
  const CampaignConfig& config = campaign.config;
  if (campaign.dataset) {
    if (!fit_dataset_folds(*campaign.dataset, config, progress, stop)) return false;
    campaign.loops = dataset_loops(config, *campaign.dataset);
    return true;
  }
  if (config.training.recordings.empty() && config.training.recordings_per_pair > 0 &&
      !loop::synthesise_training_set(simulated_training(campaign), progress, stop))
    return false;
  if (needs_classifier(config)) {
    const fs::path training = campaign.directory / "training";
    fs::create_directories(training);
    campaign.observation_model = classifier(campaign, progress, stop);
    if (!campaign.observation_model) return false;
    for (std::size_t a = 0; a < config.arms.size(); ++a) {
      if (!config.arms[a].calibrate) continue;
      const std::string file = (training / (config.arms[a].name + ".problem.yaml")).string();
      campaign.arm_problems[a] =
          loop::calibrate_problem(*campaign.arm_problems[a], *campaign.observation_model, file);
      loop::save_problem(*campaign.arm_problems[a], file);
    }
  }
  campaign.loops = make_loops(campaign);
  return true;
}

std::vector<TrialJob> remaining_jobs(const Campaign& campaign, const Shard& shard) {
  std::set<int> done;
  for (const JournalEntry& e : read_journal(campaign.directory / kJournal)) done.insert(e.id);
  std::vector<TrialJob> jobs;
  for (const TrialJob& job : campaign_jobs(campaign.config))
    if (shard.contains(job.id) && !done.count(job.id)) jobs.push_back(job);
  return jobs;
}

namespace {

// A simulated world's training set as the reference's classifier hears it (the page's comparison
// with the lab's counts); empty for other worlds, a reference without `heard`, or no training set.
std::vector<HeardCounts> heard_training_set(const Campaign& campaign) {
  const std::optional<ReferenceResults>& reference = campaign.config.reference;
  const fs::path recordings = training_recordings(campaign);
  if (!simulated(campaign.config) || !reference || !reference->heard ||
      !fs::is_directory(recordings))
    return {};
  std::vector<HeardCounts> heard;
  for (const perception::HeardConfusion& h : perception::heard_confusion(
           perception::load_recording_set(recordings.string()), reference->heard->classifier))
    heard.push_back({h.action, h.confusion.objects, h.confusion.symbols, h.confusion.counts});
  return heard;
}

}  // namespace

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
  results.heard = heard_training_set(campaign);
  write_tables(dir, results);
  write_file_atomically(dir / "summary.json", summary_json(results).dump(2) + "\n");
  const std::string text = summary_text(results);
  write_file_atomically(dir / "summary.txt", text);
  if (figures) {
    const std::vector<TemplateMatrix> templates =
        campaign.dataset ? std::vector<TemplateMatrix>{}
                         : template_matrices(training_recordings(campaign),
                                             campaign.training_objects, campaign.training_actions);
    const std::vector<Figure> drawn = draw_figures(dir, results, templates);
    write_file_atomically(dir / "index.html", html_report(dir, results, drawn));
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
    const nlohmann::json j = nlohmann::json::parse(
        read_text_file(described.string(), "campaign description"), nullptr, false);
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
