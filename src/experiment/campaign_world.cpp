#include "experiment/campaign_world.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>

#include "common/error.h"
#include "experiment/campaign_noise.h"
#include "experiment/dataset_campaign.h"
#include "experiment/report_inputs.h"
#include "experiment/unheard_choice.h"
#include "loop/calibrated_problem.h"
#include "loop/loop.h"
#include "loop/object_problem.h"
#include "loop/prepare_observation.h"
#include "loop/streams.h"
#include "perception/heard_confusion.h"
#include "sim/random_tables.h"
#include "sim/sound_action.h"
#include "sim/table_choice.h"

namespace echoplan::experiment {

namespace fs = std::filesystem;

namespace {

// The file's name without its folder and extension, for the page's title.
std::string title_of(const CampaignConfig& config) {
  return "echoplan campaign: " + fs::path(config.source).stem().string();
}

// The page's sentence on the noise every recording is heard through ("" for none).
std::string heard_through(const NoiseConfig& noise) {
  if (!noise.given()) return "";
  return fmt::format(
      " Every recording is heard through background noise ({}) at {} dB event-to-background "
      "ratio, the same noise on every arm.",
      fmt::join(noise.sources, ", "), noise.ebr_db);
}

// Problem files decide the objects, actions and rewards; the world is the world problem's table
// (model) or the simulator with the trained classifier (simulated).
class ProblemFileWorld final : public CampaignWorld {
 public:
  ProblemFileWorld(bool simulates, fs::path directory)
      : simulates_(simulates), training_(std::move(directory) / "training") {}

  void open(const CampaignConfig& config, const std::vector<ResolvedArm>& arms,
            CampaignResults& results, InputFiles& files) override;
  std::optional<ArmLoops> prepare(const CampaignConfig& config, std::vector<ResolvedArm>& arms,
                                  const ProgressFn& progress, const std::atomic<bool>& stop,
                                  int workers) const override;

 private:
  // A trained classifier is needed: an arm calibrates, or the simulator's sound is heard.
  bool needs_classifier(const std::vector<ResolvedArm>& arms) const;
  void load_problems(const CampaignConfig& config, const std::vector<ResolvedArm>& arms,
                     CampaignResults& results, InputFiles& files);
  void check_objects(const CampaignConfig& config, const pomdp::ModelSpec& spec);
  void load_simulator(const CampaignConfig& config, InputFiles& files);
  void load_given_model(const CampaignConfig& config, const std::vector<ResolvedArm>& arms,
                        InputFiles& files);
  WorldPresentation presentation(const CampaignConfig& config) const;
  loop::SimulatedTraining simulated_training(const CampaignConfig& config) const;
  void load_surfaces(const CampaignConfig& config, const std::vector<ResolvedArm>& arms);
  std::shared_ptr<const perception::ObservationModel> classifier(
      const CampaignConfig& config, const ProgressFn& progress,
      const std::atomic<bool>& stop) const;
  std::shared_ptr<const perception::ObservationModel> classifier_in_noise(
      const CampaignConfig& config, const ProgressFn& progress,
      const std::atomic<bool>& stop) const;
  std::shared_ptr<const perception::ObservationModel> classifier_on_surfaces(
      const CampaignConfig& config, const ProgressFn& progress,
      const std::atomic<bool>& stop) const;
  // The arms' problems and the classifiers as prepare() made them: each arm's problem as its file
  // says, a calibrating arm's calibrated; the classifier trained in quiet and, when an arm is
  // trained in noise, the one trained in noise too.
  struct Prepared {
    std::vector<std::shared_ptr<const pomdp::Problem>> arm_problems;
    std::shared_ptr<const perception::ObservationModel> model;
    std::shared_ptr<const perception::ObservationModel> model_in_noise;
    std::shared_ptr<const perception::ObservationModel> model_on_surfaces = nullptr;
    const std::shared_ptr<const perception::ObservationModel>& of(const ResolvedArm& arm) const {
      if (arm.trained_on_surfaces) return model_on_surfaces;
      return arm.trained_in_noise() ? model_in_noise : model;
    }
  };
  ArmLoops make_loops(const CampaignConfig& config, const std::vector<ResolvedArm>& arms,
                      const Prepared& prepared) const;
  std::optional<std::vector<HeardCounts>> heard(const CampaignConfig& config,
                                                const std::atomic<bool>& stop) const;
  bool keep_report_inputs(const CampaignConfig& config, const std::atomic<bool>& stop) const;

  bool simulates_;
  fs::path training_;    // DIR/training: the model, the calibrated problems
  fs::path recordings_;  // the training set: training_set.recordings or DIR/training/recordings
  std::vector<std::string> training_objects_, training_actions_;
  std::shared_ptr<const pomdp::Problem> world_problem_;
  std::vector<std::shared_ptr<const pomdp::Problem>> arm_problems_;  // as their files say
  std::shared_ptr<const sim::Catalogue> catalogue_;
  // world.surface and training_set.surfaces with their random:N entries drawn (load_simulator).
  std::vector<std::string> world_tables_, training_tables_;
  std::shared_ptr<const sim::SimConfig> sim_config_;
  std::shared_ptr<const sim::SimConfig> world_sim_config_;     // the trials': on world.surface
  std::shared_ptr<const sim::SimConfig> surfaces_sim_config_;  // training_set.surfaces'
  std::shared_ptr<const perception::ObservationModel> given_model_;  // training_set.model
  CampaignNoise noise_;
};

bool any_trained_on_surfaces(const std::vector<ResolvedArm>& arms) {
  return std::any_of(arms.begin(), arms.end(),
                     [](const ResolvedArm& a) { return a.trained_on_surfaces; });
}

// Training on `recordings` as the campaign trains (training_set's classifier and table), the model
// saved to `saved` for the user.
loop::RecordingsTraining campaign_training(const CampaignConfig& config, const fs::path& recordings,
                                           const fs::path& saved) {
  loop::RecordingsTraining training{recordings.string(), {}, saved.string()};
  if (!config.training.classifier.empty()) training.train.classifier = config.training.classifier;
  if (!config.training.table.empty())
    training.train.table = perception::parse_table_estimate(config.training.table);
  // Every arm must hear the same symbols to be compared trial by trial: no reject option.
  training.train.reject = false;
  training.train.seed = loop::stream_seed(config.seed, loop::Stream::campaign_folds);
  return training;
}

// The model an earlier run of the campaign trained and saved.
std::shared_ptr<const perception::ObservationModel> saved_model(const fs::path& saved,
                                                                const ProgressFn& progress,
                                                                const std::atomic<bool>& stop) {
  return loop::prepare_observation(loop::ModelFile{saved.string()}, nullptr, "", progress, stop)
      .model;
}

bool ProblemFileWorld::needs_classifier(const std::vector<ResolvedArm>& arms) const {
  return simulates_ ||
         std::any_of(arms.begin(), arms.end(), [](const ResolvedArm& a) { return a.calibrate; });
}

// The problems: each loads, and all share objects, actions and observations with the world.
void ProblemFileWorld::load_problems(const CampaignConfig& config,
                                     const std::vector<ResolvedArm>& arms, CampaignResults& results,
                                     InputFiles& files) {
  world_problem_ = files.problem(config.world.problem);
  const pomdp::ModelSpec& spec = world_problem_->model->spec();
  if (spec.state.discrete_value_names.empty())
    throw InputError(config.world.problem, 0,
                     "a campaign needs an object-identification problem (objects as its state)");
  for (const ResolvedArm& arm : arms) {
    arm_problems_.push_back(files.problem(arm.problem));
    loop::check_same_names(*arm_problems_.back(), *world_problem_);
    check_arm_problem(config, arm, *arm_problems_.back());
  }
  results.spec = spec;
  results.action_costs = action_costs(*world_problem_->model);
  const auto particles = [](const pomdp::Problem& p) {
    return p.belief.type == pomdp::BeliefSettings::Type::particle ? p.belief.particles : 0;
  };
  results.belief_particles = particles(*arm_problems_.front());
  for (const auto& p : arm_problems_)
    if (particles(*p) != results.belief_particles)
      results.belief_particles = 0;  // arms disagree: show probabilities
}

// Objects: each group plays an object of the problems, and every object named has a catalogue
// entry. Fills the training set's objects and actions.
void ProblemFileWorld::check_objects(const CampaignConfig& config, const pomdp::ModelSpec& spec) {
  const auto& objects = spec.state.discrete_value_names[0];
  for (const ObjectGroup& g : config.groups)
    if (std::find(objects.begin(), objects.end(), g.plays) == objects.end())
      throw InputError(config.source, 0,
                       fmt::format("trial group '{}' plays '{}', which is not an object of {}",
                                   g.object, g.plays, config.world.problem));
  training_objects_ = config.training.objects.empty() ? objects : config.training.objects;
  training_actions_ = config.training.actions;
  // By default the problems' sound-making actions the simulator can perform.
  if (training_actions_.empty())
    for (const auto& a : spec.action_names)
      if (sim::find_sound_action(a)) training_actions_.push_back(a);
  std::vector<std::string> named = training_objects_;
  for (const ObjectGroup& g : config.groups) named.push_back(g.object);
  for (const std::string& o : objects) named.push_back(o);
  const auto known = catalogue_->object_names();
  for (const std::string& name : named)
    if (std::find(known.begin(), known.end(), name) == known.end())
      throw InputError(config.source, 0,
                       fmt::format("object '{}' has no entry in the catalogue {} (it has: {})",
                                   name, catalogue_->source, fmt::join(known, ", ")));
}

// The simulator's inputs: the catalogue and the sim config, loaded once.
void ProblemFileWorld::load_simulator(const CampaignConfig& config, InputFiles& files) {
  const TrainingSetConfig& t = config.training;
  const std::string catalogue = t.catalogue.empty() ? sim::default_catalogue_path() : t.catalogue;
  sim::Catalogue loaded = sim::parse_catalogue(files.text(catalogue), catalogue);
  // `random:N` tables, drawn from the campaign's seed: the world's and the training set's apart,
  // so a world on random tables never meets one its training set heard.
  auto expand = [&](const std::vector<std::string>& names, const std::string& tag, int line) {
    try {
      return sim::expand_random_tables(loaded, names, config.seed, tag);
    } catch (const InputError& e) {
      throw InputError(config.source, line, e.problem());
    }
  };
  world_tables_ = expand(config.world.surfaces, "world", config.world.surface_line);
  training_tables_ = expand(t.surfaces, "training", t.surfaces_line);
  catalogue_ = std::make_shared<const sim::Catalogue>(std::move(loaded));
  sim_config_ = std::make_shared<const sim::SimConfig>(
      t.sim_config.empty() ? sim::SimConfig{}
                           : sim::parse_sim_config(files.text(t.sim_config), t.sim_config));
}

// training_set.model: one for these objects and actions, checked against every calibrating arm
// and every loop now.
void ProblemFileWorld::load_given_model(const CampaignConfig& config,
                                        const std::vector<ResolvedArm>& arms, InputFiles& files) {
  given_model_ =
      std::make_shared<const perception::ObservationModel>(perception::parse_observation_model(
          files.text(config.training.model), config.training.model));
  // The loops are checked with the problems the arms will plan with: a graded arm's calibrated
  // problem hears the graded symbols its world makes.
  std::vector<std::shared_ptr<const pomdp::Problem>> problems = arm_problems_;
  for (std::size_t a = 0; a < arms.size(); ++a)
    if (arms[a].calibrate)
      problems[a] =
          loop::calibrate_problem(*arm_problems_[a], *given_model_, "", arms[a].hearing());
  make_loops(config, arms, Prepared{problems, given_model_, nullptr});
}

WorldPresentation ProblemFileWorld::presentation(const CampaignConfig& config) const {
  WorldPresentation p;
  p.title = title_of(config);
  if (simulates_)
    p.note =
        "The world here is the simulator: the simulated robot slides or strikes the object (a "
        "weighted variant with its added mass), the simulated recorder records, and the "
        "classifier trained on the synthesised training set reports what it heard. If simulated "
        "objects are easier to tell apart than the lab's real ones, the numbers here are better "
        "than the report's for that reason, not because of the planner." +
        heard_through(config.world.noise);
  else
    p.note = fmt::format(
        "The world here is a problem file's own observation table ({}): "
        "observations are drawn from it, no sound is synthesised or classified during the trials, "
        "and a variant object (e.g. a weighted can) behaves exactly as the object it plays. These "
        "trials measure the planner; they say nothing about how well sound tells the objects "
        "apart.",
        config.world.problem);
  return p;
}

// The sim config on `tables` (InputError at `line` of the campaign for one the catalogue lacks).
std::shared_ptr<const sim::SimConfig> on_tables(const sim::SimConfig& base,
                                                const sim::Catalogue& catalogue,
                                                const std::vector<std::string>& tables,
                                                const CampaignConfig& config, int line) {
  sim::SimConfig on = base;
  on.tables = tables;
  try {
    sim::check_tables(catalogue, on);
  } catch (const InputError& e) {
    throw InputError(config.source, line, e.problem());
  }
  return std::make_shared<const sim::SimConfig>(std::move(on));
}

// The trials' tables (world.surface) and, for an arm trained on surfaces, its training set's
// (training_set.surfaces).
void ProblemFileWorld::load_surfaces(const CampaignConfig& config,
                                     const std::vector<ResolvedArm>& arms) {
  const std::vector<std::string>& world = world_tables_;
  world_sim_config_ = world.empty() ? sim_config_
                                    : on_tables(*sim_config_, *catalogue_, world, config,
                                                config.world.surface_line);
  const TrainingSetConfig& t = config.training;
  if (any_trained_on_surfaces(arms) == t.surfaces.empty())
    throw InputError(config.source, t.surfaces_line,
                     t.surfaces.empty()
                         ? "an arm trained_on_surfaces needs training_set.surfaces: the tables "
                           "its training set is recorded on"
                         : "training_set.surfaces is what an arm `trained_on_surfaces` learns "
                           "from, and no arm is");
  if (t.surfaces.empty()) return;
  if (!t.model.empty() || !t.recordings.empty() || t.recordings_per_pair == 0)
    throw InputError(config.source, t.surfaces_line,
                     "training_set.surfaces records a training set: it needs recordings_per_pair "
                     "> 0 and no training_set.model or recordings");
  surfaces_sim_config_ =
      on_tables(*sim_config_, *catalogue_, training_tables_, config, t.surfaces_line);
}

void ProblemFileWorld::open(const CampaignConfig& config, const std::vector<ResolvedArm>& arms,
                            CampaignResults& results, InputFiles& files) {
  recordings_ = config.training.recordings.empty() ? training_ / "recordings"
                                                   : fs::path(config.training.recordings);
  load_problems(config, arms, results, files);
  load_simulator(config, files);
  check_objects(config, results.spec);
  noise_ = load_campaign_noise(config, arms);
  load_surfaces(config, arms);
  results.world = presentation(config);
  results.groups = config.groups;
  if (!config.training.recordings.empty() && !fs::is_directory(config.training.recordings))
    throw InputError(config.training.recordings, 0, "the recordings folder does not exist");
  if (!config.training.model.empty() && needs_classifier(arms))
    load_given_model(config, arms, files);
  else if (needs_classifier(arms) && config.training.recordings_per_pair == 0 &&
           config.training.recordings.empty())
    throw InputError(
        config.source, 0,
        "a calibrating arm or a simulated world needs a classifier: give training_set.model, "
        "training_set.recordings or recordings_per_pair > 0");
}

// The campaign's training set as the loop synthesises it.
loop::SimulatedTraining ProblemFileWorld::simulated_training(const CampaignConfig& config) const {
  loop::SimulatedTraining t;
  t.catalogue = catalogue_;
  t.config = sim_config_;
  t.objects = training_objects_;
  t.actions = training_actions_;
  t.per_pair = config.training.recordings_per_pair;
  t.seed = loop::stream_seed(config.seed, loop::Stream::campaign_training);
  t.directory = recordings_;
  t.reuse_complete = true;
  return t;
}

// The classifier: training_set.model (loaded already), DIR/training/model.json of an earlier run,
// or trained now on the training set (and saved there for the user). Null when stopped.
std::shared_ptr<const perception::ObservationModel> ProblemFileWorld::classifier(
    const CampaignConfig& config, const ProgressFn& progress, const std::atomic<bool>& stop) const {
  if (given_model_) return given_model_;
  const fs::path saved = training_ / "model.json";
  if (fs::exists(saved)) return saved_model(saved, progress, stop);
  return loop::prepare_observation(campaign_training(config, recordings_, saved), nullptr, "",
                                   progress, stop)
      .model;
}

// The classifier an arm trained in noise hears with: DIR/training/model_in_noise.json of an
// earlier run, or trained now on the training set and its noisy twins (DIR/training/
// recordings_in_noise), cross-validated by twin so that no recording is tested against its own.
std::shared_ptr<const perception::ObservationModel> ProblemFileWorld::classifier_in_noise(
    const CampaignConfig& config, const ProgressFn& progress, const std::atomic<bool>& stop) const {
  const fs::path saved = training_ / "model_in_noise.json";
  if (fs::exists(saved)) return saved_model(saved, progress, stop);
  const fs::path copy = training_ / "recordings_in_noise";
  if (!write_campaign_copy(config, recordings_, *noise_.training, copy,
                           loop::Stream::campaign_noise, /*keep_quiet=*/true, progress, stop))
    return nullptr;
  loop::RecordingsTraining training = campaign_training(config, copy, saved);
  training.train.cross_validation = perception::CrossValidation::by_session;
  return loop::prepare_observation(training, nullptr, "", progress, stop).model;
}

// The classifier an arm trained on surfaces hears with: DIR/training/model_on_surfaces.json of an
// earlier run, or trained now on its own training set (DIR/training/recordings_on_surfaces), the
// first's seeds recorded on training_set.surfaces.
std::shared_ptr<const perception::ObservationModel> ProblemFileWorld::classifier_on_surfaces(
    const CampaignConfig& config, const ProgressFn& progress, const std::atomic<bool>& stop) const {
  const fs::path saved = training_ / "model_on_surfaces.json";
  if (fs::exists(saved)) return saved_model(saved, progress, stop);
  loop::SimulatedTraining on_surfaces = simulated_training(config);
  on_surfaces.config = surfaces_sim_config_;
  on_surfaces.directory = training_ / "recordings_on_surfaces";
  if (!loop::synthesise_training_set(on_surfaces, progress, stop)) return nullptr;
  return loop::prepare_observation(campaign_training(config, on_surfaces.directory, saved), nullptr,
                                   "", progress, stop)
      .model;
}

std::optional<ArmLoops> ProblemFileWorld::prepare(const CampaignConfig& config,
                                                  std::vector<ResolvedArm>& arms,
                                                  const ProgressFn& progress,
                                                  const std::atomic<bool>& stop,
                                                  int workers) const {
  if (config.training.recordings.empty() && config.training.recordings_per_pair > 0 &&
      !loop::synthesise_training_set(simulated_training(config), progress, stop))
    return std::nullopt;
  Prepared prepared{arm_problems_, nullptr, nullptr};
  if (needs_classifier(arms)) {
    fs::create_directories(training_);
    prepared.model = classifier(config, progress, stop);
    if (!prepared.model) return std::nullopt;
    if (any_trained_in_noise(arms)) {
      prepared.model_in_noise = classifier_in_noise(config, progress, stop);
      if (!prepared.model_in_noise) return std::nullopt;
    }
    if (any_trained_on_surfaces(arms)) {
      prepared.model_on_surfaces = classifier_on_surfaces(config, progress, stop);
      if (!prepared.model_on_surfaces) return std::nullopt;
    }
    for (std::size_t a = 0; a < arms.size(); ++a) {
      if (!arms[a].calibrate) continue;
      const std::string file = (training_ / (arms[a].name + ".problem.yaml")).string();
      prepared.arm_problems[a] = loop::calibrate_problem(*arm_problems_[a], *prepared.of(arms[a]),
                                                         file, arms[a].hearing());
      loop::save_problem(*prepared.arm_problems[a], file);
    }
  }
  // Arms that leave the unheard estimate to self-play play their own (calibrated) problem, its
  // belief tracked exactly; arms of one problem share the copy, and so one choice.
  std::map<const pomdp::Problem*, std::shared_ptr<const pomdp::Problem>> exact;
  const auto problems_of = [&](std::size_t arm) {
    auto& p = exact[prepared.arm_problems[arm].get()];
    if (!p) p = with_exact_belief(prepared.arm_problems[arm]);
    return std::vector<std::shared_ptr<const pomdp::Problem>>{p};
  };
  if (!choose_arms_unheard(config, arms, problems_of, training_.parent_path(), progress, stop,
                           workers) ||
      !keep_report_inputs(config, stop))
    return std::nullopt;
  return make_loops(config, arms, prepared);
}

// The page's view of the training set (heard counts, templates), worked out once per campaign
// folder: an earlier run's file is kept (the folder holds one campaign, so it cannot differ).
// False when stopped.
bool ProblemFileWorld::keep_report_inputs(const CampaignConfig& config,
                                          const std::atomic<bool>& stop) const {
  const fs::path directory = training_.parent_path();
  if (fs::exists(directory / kReportInputs)) return true;
  ReportInputs inputs;
  std::optional<std::vector<HeardCounts>> heard_counts = heard(config, stop);
  if (!heard_counts) return false;
  inputs.heard = std::move(*heard_counts);
  if (fs::is_directory(recordings_))
    inputs.templates = template_matrices(recordings_, training_objects_, training_actions_);
  write_report_inputs(directory, inputs);
  return true;
}

// The checked loop of every arm and group; InputError when a part does not fit.
ArmLoops ProblemFileWorld::make_loops(const CampaignConfig& config,
                                      const std::vector<ResolvedArm>& arms,
                                      const Prepared& prepared) const {
  ArmLoops loops(arms.size());
  // A graded (or levels) arm's world hears graded symbols: the world's problem with its model's
  // graded table (its rewards and kinematics as they are; the simulator, not the table, makes
  // observations).
  using GradedKey = std::pair<const perception::ObservationModel*, perception::ObservationKind>;
  std::map<GradedKey, std::shared_ptr<const pomdp::Problem>> graded_world;
  const auto key = [&](const ResolvedArm& arm) {
    return GradedKey{prepared.of(arm).get(), arm.hearing()};
  };
  for (const ResolvedArm& arm : arms)
    if (arm.hearing() != perception::ObservationKind::labels) {
      auto& world = graded_world[key(arm)];
      if (!world)
        world = loop::calibrate_problem(*world_problem_, *prepared.of(arm),
                                        world_problem_->source_path, arm.hearing());
    }
  for (std::size_t a = 0; a < arms.size(); ++a)
    for (const ObjectGroup& group : config.groups) {
      loop::LoopSettings s;
      s.problem = prepared.arm_problems[a];
      s.world_problem = arms[a].hearing() == perception::ObservationKind::labels
                            ? world_problem_
                            : graded_world.at(key(arms[a]));
      if (simulates_) {
        s.world = loop::SimulatedWorldSpec{catalogue_, world_sim_config_};
        s.observation_model = prepared.of(arms[a]);
        s.noise = noise_.world;
        if (group.object != group.plays) s.world_objects[group.plays] = group.object;
      }
      s.planner = arms[a].planner;
      s.max_steps = config.planner.max_steps;
      auto spec = std::make_shared<const loop::LoopSpec>(std::move(s));
      const int object = loop::object_index(spec->problem(), group.plays);
      loops[a].push_back({TrialLoop{std::move(spec), object, ""}});
    }
  return loops;
}

// A simulated world's training set as the reference's classifier hears it, leave-one-out, and the
// trials' variants (objects that are no class: the weighted can) heard by that classifier fitted
// on the whole training set, as the lab heard its modified objects: the page's comparison with the
// lab's counts. The variants' recordings (as many per pair as the training set's) are synthesised
// into DIR/training/variants on their own random stream. Empty for a reference without `heard`,
// or no training set; nothing when stopped.
std::optional<std::vector<HeardCounts>> ProblemFileWorld::heard(
    const CampaignConfig& config, const std::atomic<bool>& stop) const {
  const std::optional<ReferenceResults>& reference = config.reference;
  if (!simulates_ || !reference || !reference->heard || !fs::is_directory(recordings_))
    return std::vector<HeardCounts>{};
  const perception::RecordingSet training = perception::load_recording_set(recordings_.string());
  loop::SimulatedTraining variants = simulated_training(config);
  variants.objects.clear();
  for (const ObjectGroup& group : config.groups)
    if (std::find(training.objects.begin(), training.objects.end(), group.object) ==
            training.objects.end() &&
        std::find(variants.objects.begin(), variants.objects.end(), group.object) ==
            variants.objects.end())
      variants.objects.push_back(group.object);
  variants.actions = training.actions;
  variants.seed = loop::stream_seed(config.seed, loop::Stream::campaign_variants);
  variants.directory = training_ / "variants";
  const bool hear_variants = !variants.objects.empty() && variants.per_pair > 0;
  if (hear_variants && !loop::synthesise_training_set(variants, {}, stop)) return std::nullopt;
  const std::vector<perception::HeardConfusion> confusions =
      hear_variants ? perception::heard_confusion(
                          training, perception::load_recording_set(variants.directory.string()),
                          reference->heard->classifier)
                    : perception::heard_confusion(training, reference->heard->classifier);
  std::vector<HeardCounts> heard;
  for (const perception::HeardConfusion& h : confusions)
    heard.push_back({h.action, h.confusion.objects, h.confusion.symbols, h.confusion.counts});
  return heard;
}

// Recorded data: the data and its folds instead of problem files, the simulator and trial groups.
class RecordedDataWorld final : public CampaignWorld {
 public:
  explicit RecordedDataWorld(fs::path directory) : directory_(std::move(directory)) {}
  void open(const CampaignConfig& config, const std::vector<ResolvedArm>& arms,
            CampaignResults& results, InputFiles& files) override;
  std::optional<ArmLoops> prepare(const CampaignConfig& config, std::vector<ResolvedArm>& arms,
                                  const ProgressFn& progress, const std::atomic<bool>& stop,
                                  int workers) const override {
    DatasetFolds fitted = *trials_;  // the data and folds shared; the models are this run's
    if (!hear_dataset_in_noise(fitted, config, noise_, directory_, progress, stop) ||
        !fit_dataset_folds(fitted, config, arms, progress, stop))
      return std::nullopt;
    const FoldProblems problems = fold_problems(config, arms, fitted);
    write_fold_problems(directory_, config, problems);
    if (!choose_dataset_unheard(directory_, config, arms, problems, progress, stop, workers))
      return std::nullopt;
    return dataset_loops(config, arms, fitted);
  }

 private:
  fs::path directory_;  // the campaign's folder: each fold's problem goes to folds/<fold>/
  std::shared_ptr<const DatasetFolds> trials_;
  CampaignNoise noise_;
};

void RecordedDataWorld::open(const CampaignConfig& config, const std::vector<ResolvedArm>& arms,
                             CampaignResults& results, InputFiles& files) {
  trials_ = std::make_shared<DatasetFolds>(open_dataset(config, arms, files));
  noise_ = load_campaign_noise(config, arms);
  results.groups = dataset_groups(*trials_);
  // Every arm against the names problem now, not in a worker.
  for (const ResolvedArm& arm : arms) check_arm_problem(config, arm, *trials_->names);
  results.spec = trials_->names->model->spec();
  results.right_action = right_actions(*trials_);
  results.right_share = right_shares(*trials_, config.task);
  results.sensing_actions = static_cast<int>(trials_->data->actions.size());
  results.action_costs = action_costs(*trials_->names->model);
  for (std::size_t s = 0; s < trials_->data->sessions.size(); ++s) {
    const perception::Session& session = trials_->data->sessions[s];
    results.fold_of_session[{trials_->data->objects.at(session.object), session.name}] =
        std::to_string(trials_->fold_of_session.at(s) + 1);
  }
  results.world.title = title_of(config);
  results.world.note = config.world.model.empty()
                           ? "The world here is recorded data replayed: each trial is one "
                             "session of one object, heard by the model fitted on the folds "
                             "that do not hold it." +
                                 heard_through(config.world.noise)
                           : "The world here is recorded data replayed: each trial is one "
                             "session of one object, heard by a frozen model trained beforehand.";
  results.world.arm_problem =
      config.world.model.empty() ? "each fold's problem" : "the frozen model's problem";
  results.world.pairing = "same objects, same recorded sessions";
  results.world.per_object = false;
}

}  // namespace

std::unique_ptr<CampaignWorld> make_campaign_world(const CampaignConfig& config,
                                                   const fs::path& directory) {
  switch (config.world.type) {
    case WorldType::model:
      return std::make_unique<ProblemFileWorld>(false, directory);
    case WorldType::simulated:
      return std::make_unique<ProblemFileWorld>(true, directory);
    case WorldType::dataset:
      break;
  }
  return std::make_unique<RecordedDataWorld>(directory);
}

}  // namespace echoplan::experiment
