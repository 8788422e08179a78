// A campaign: the report's chapter 5 as data. Which training set to synthesise, which problems the
// arms plan with, which objects the world holds and how often, the planner's budget and the seed.
//
// Read from YAML (format and defaults: experiments/chapter5.yaml, docs/experiment.md). Relative
// paths in the file are relative to the file's folder. Everything is checked at load time, so a
// campaign never fails halfway through because of its configuration. The file's sections are
// described once (campaign_config.cpp, with config_fields.h): the YAML reading, campaign.json and
// the identity all follow that description.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "experiment/input_files.h"
#include "experiment/reference_results.h"
#include "loop/dataset_problem.h"
#include "perception/dataset_task.h"
#include "perception/observation_grades.h"
#include "perception/recording_features.h"

namespace echoplan::experiment {

// The strategy of an arm that plans with the campaign's planner.
inline constexpr const char* kPlanStrategy = "plan";
// An arm's `unheard` when the campaign chooses it by self-play on the arm's own problems.
inline constexpr const char* kUnheardByPlay = "auto";

// One arm of the campaign (a study arm, not the robot's: that is sim::ArmConfig) in the file's
// words: the same trials decided by one strategy with one problem. What it runs, defaults applied
// and rules checked, is its ResolvedArm (campaign_arms.h).
struct CampaignArm {
  std::string name;  // a label: letters, digits, '_' and '-'
  // Path of the problem file the arm decides with; empty in a dataset world, where each fold's
  // problem is built from the data.
  std::string problem;
  // Plan with `problem`'s observation table replaced by the trained classifier's calibrated one
  // (what calibration buys is this arm against one planning with the file's own table).
  bool calibrate = false;
  // "plan": the campaign's planner; else a fixed strategy by its solver name (all_actions,
  // best_single, decision_region, information_gain, random: solvers/solver_factory.h), the
  // baselines a planner is measured against.
  std::string strategy = kPlanStrategy;
  // What the arm hears (perception/observation_grades.h): "labels", the class a performance was
  // heard as; or "graded", the class and how sure the classifier was (a calibrating arm of a
  // simulated world, or any arm of a dataset world).
  std::string observations = "labels";
  perception::ObservationKind observation_kind() const;
  // A dataset world's arm that plans knowing some objects sound like another class
  // (perception/typicality.h, lookalikes): each class has a lookalike copy with the share its
  // fold's model fitted on held-out data (loop/dataset_problem.h). When one arm does, every arm's
  // problem has the copies (with a share of 0 for the others, which then plan exactly as without
  // them), so all arms' beliefs name the same states. Absent: the default (campaign_arms.h: with
  // them for a planner sorting novel objects).
  std::optional<bool> lookalike{};
  // An arm of strategy `plan`: the planner's leaf value (solvers/leaf_value.h: policy, exact, ...);
  // empty: the solver's default for the problem.
  std::string leaf{};
  // An arm of strategy `plan`: how ABT counts outcomes no episode has heard yet (share or commit,
  // solvers/search_tree.h), or kUnheardByPlay: the one that earns more on the arm's own problems
  // (experiment/unheard_choice.h); empty: share. An arm that plans with ABT and a leaf that can
  // commit, in a world that holds out objects, has commit unless it names another.
  std::string unheard{};
  // Hears with the classifier trained on the training set and on a noisy copy of it
  // (training_set.noise: multi-condition training), not the one trained in quiet alone.
  bool trained_in_noise = false;
  // Hears with the classifier trained on the training set recorded on training_set.surfaces (the
  // catalogue's other tables), not the one trained on the sim config's table alone.
  bool trained_on_surfaces = false;
  // A dataset world's arm that hears with a model fitted on these modalities of the data only
  // (audio alone, a torque sensor alone, ...); empty: every modality.
  std::vector<std::string> modalities{};
  int line = 0;  // where the file gives the arm (0: not read from a file); not a setting
};

// A group of trials with one object in the world. `object` is what the world holds (a catalogue
// name, e.g. "pringles_can_weighted"); `plays` is the problem's object that counts as the truth
// (the object it is a variant of, e.g. "pringles_can"); equal for an original object.
struct ObjectGroup {
  std::string object;
  std::string plays;
  int trials = 10;  // >= 1
};

// Where actions happen.
enum class WorldType {
  // `model`: the world draws observations from `problem`'s own table (a planner study, no sound);
  // a variant object behaves as the object it plays.
  model,
  // `simulated`: the closed loop: the simulated robot acts on the group's object, the simulated
  // recorder records, the trained classifier hears; `problem` gives rewards, kinematics and
  // symbols.
  simulated,
  // `dataset`: recorded data replayed: each trial is one (object, session) of a feature set or a
  // recordings tree, heard by the model fitted on the other folds, or by a frozen model file
  // (loop/dataset_world.h).
  dataset,
};

// The kinds of world, declared once: the campaign file's word for each, and whether it replays
// recorded data (its configuration then names data instead of problem files and trial groups).
struct WorldKind {
  WorldType type;
  const char* word;  // "model", "simulated", "dataset"
  bool recorded_data;
};
const WorldKind& world_kind(WorldType type);
// The kind whose word is `word`; InputError listing the words for another.
const WorldKind& world_kind(std::string_view word);

// world_kind(type).word.
const char* to_string(WorldType type);

// Background noise recordings are heard with (robot/noisy_recorder.h, docs/noise.md): its sources
// (built-in names, recordings, folders of them; paths relative to the campaign file) and the
// event-to-background ratio of each recording, "X" or a range "LO:HI" in dB drawn per recording.
struct NoiseConfig {
  std::vector<std::string> sources;  // empty: none
  std::string ebr_db;
  int talkers = 1;  // recorded sources heard at once (sim/background_noise.h: babble)
  bool given() const { return !sources.empty(); }
};

struct WorldConfig {
  WorldType type = WorldType::model;
  std::string problem;  // model and simulated worlds
  // Dataset worlds: the data (a feature set or a recordings tree), what a trial holds out
  // ("session" or "object") and the groups file the objects are sorted by (empty: by object).
  std::string data;
  perception::HoldOut hold_out = perception::HoldOut::session;
  std::string groups;
  // How a recordings tree's series become rows, by modality (signal/series_features.h specs; a
  // modality not named: bins(10,mean)).
  perception::SeriesChoices series;
  // A frozen observation model file (`echoplan train --out`): no folds, every session replayed
  // with it (a model trained one day, judged on data recorded another). Empty: fit per fold.
  std::string model;
  // The background noise every recording of every trial is heard through, the same on every arm
  // (none: as recorded, or the simulated lab's quiet): a simulated world's, or a dataset world's
  // over a recordings tree (a noisy copy of the tree, each recording's noise its own).
  NoiseConfig noise;
  // A simulated world's tables (`surface:`, catalogue names): one for every trial, or a list, one
  // drawn per trial from its seed (the same on every arm; sim/table_choice.h). Empty: the sim
  // config's. `surface_line`: where the file gives it (0: not read from a file).
  std::vector<std::string> surfaces;
  int surface_line = 0;
  // The world replays recorded data (world_kind(type).recorded_data).
  bool recorded_data() const;
};

// The training set synthesised before the trials (`echoplan synth-recordings`'s library code).
struct TrainingSetConfig {
  int recordings_per_pair = 10;      // 0: no synthesis (and no template figures)
  std::vector<std::string> objects;  // catalogue names; empty: the planning problems' objects
  std::vector<std::string> actions;  // empty: the planning problems' sensing actions
  std::string recordings;  // an existing DIR/<object>/<action>/*.wav folder to use instead
                           // of synthesising (e.g. real recordings); empty: synthesise
  std::string model;       // an existing trained model file to use instead of training on the
                           // training set; empty: train
  std::string classifier;  // perception's classifier name; empty: its default
  std::string table;       // perception's table estimate ("counts" or "soft"); empty: its default
  std::string catalogue;   // empty: the shipped catalogue
  std::string sim_config;  // empty: built-in defaults
  // The noise of the noisy copy of the training set that an arm `trained_in_noise` also learns
  // from (multi-condition training); sources default to the world's, the ratio to "-6:24".
  NoiseConfig noise;
  // The tables (catalogue names) of the training set an arm `trained_on_surfaces` learns from,
  // synthesised beside the first on the same seeds, recording i of each pair on table i mod n.
  // `surfaces_line`: where the file gives them.
  std::vector<std::string> surfaces;
  int surfaces_line = 0;
};

struct PlannerConfig {
  std::string solver = "abt";  // "abt" or "pomcp"
  std::int64_t episodes = 0;   // search episodes per step (reproducible); exactly one budget > 0
  std::int64_t step_ms = 0;    // wall time per step (not reproducible bit for bit)
  int max_steps = 100;         // a trial stops after this many steps
  // Paired trials per estimate that an arm with `unheard: auto` plays on its own problems.
  int self_play_trials = 200;
};

struct CampaignConfig {
  std::string source;  // the file it was read from
  std::uint64_t seed = 1;
  std::vector<CampaignArm> arms;
  WorldConfig world;
  TrainingSetConfig training;
  std::vector<ObjectGroup> groups;  // trials per object, in report order (a dataset world: one
                                    // group per object of the data, a trial per session)
  loop::TaskSpec task;              // dataset worlds (a problem file has its own)
  PlannerConfig planner;
  // What the results are shown beside (the file named by `reference:`); none: no reference
  // columns. Not part of the identity: it changes the report's comparison, not the trials.
  std::optional<ReferenceResults> reference;

  // Everything that decides the results, as JSON with files and data folders replaced by their
  // fingerprints, so a resumed or merged run can check it continues the same campaign: the
  // configuration with the world's `trial_groups` (a dataset world's come from its data).
  nlohmann::json identity(InputFiles& files, const std::vector<ObjectGroup>& trial_groups) const;
  // The identity with the file's own trial groups (a model or simulated world's), its files read
  // here.
  nlohmann::json identity() const;
};

// Reads a campaign file; throws InputError naming the file, the line and the problem.
CampaignConfig load_campaign_config(const std::string& path);

// As load_campaign_config, from text; `source` names it in messages and anchors relative paths.
CampaignConfig parse_campaign_config(const std::string& yaml_text, const std::string& source);

// The shipped default: experiments/chapter5.yaml in the working directory if it exists, else the
// one in the source tree echoplan was built from.
std::string default_campaign_path();

}  // namespace echoplan::experiment

namespace echoplan::experiment {

// The configuration as JSON (paths as resolved) and back, for campaign.json: a resumed run and
// `echoplan merge` rebuild the report from it. Throws InputError(source, 0, ...) for bad JSON.
nlohmann::json to_json(const CampaignConfig& config);
CampaignConfig campaign_config_from_json(const nlohmann::json& j, const std::string& source);

}  // namespace echoplan::experiment
