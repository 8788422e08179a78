// `echoplan train`: fit the one observation model (perception/fit_observation_model.h) on a data
// folder, a recordings tree or a feature set; print what cross-validation measured; save the model
// file and, when asked, the problem that plans with its calibrated table: --problem-base with the
// table replaced, or the data's own problem (classes, behaviours with their use limits, bins,
// rewards). Every fitting option is open to every kind of data; their defaults follow the
// cross-validation, whose default follows the data (fit_observation_model.h says which and why).
#include <fmt/core.h>
#include <fmt/ranges.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <map>
#include <numeric>
#include <optional>
#include <sstream>

#include "commands/commands.h"
#include "commands/perception_report.h"
#include "commands/series_options.h"
#include "common/error.h"
#include "common/file_io.h"
#include "loop/behaviour_costs.h"
#include "loop/calibrated_problem.h"
#include "loop/dataset_problem.h"
#include "perception/classifier.h"
#include "perception/observation_model.h"
#include "perception/recording_features.h"
#include "pomdp/problem.h"

namespace echoplan::cli {
namespace {

// What the user typed; fit_options() turns it into FitOptions over the defaults.
struct TrainFlags {
  std::string data;
  std::string out;
  std::string problem_out;
  std::string problem_base = "problems/audio_objects.yaml";
  std::string groups;
  std::string hold_out;
  std::string costs;
  std::vector<std::string> prerequisites;  // BEHAVIOUR=B1,B2 (--requires), as typed
  loop::TaskSpec rewards;
  std::string cross_validation;
  std::string table;
  bool reject = true;
  bool fuse = false;
  bool temper = false;
  perception::FitOptions given;     // the numbers and names as given (classifier, folds, ...)
  std::vector<std::string> series;  // MODALITY=SPEC, as typed
};

bool given(const CLI::App& cmd, const char* name) { return cmd.count(name) > 0; }

// --requires BEHAVIOUR=B1,B2 (repeatable) as TaskSpec::prerequisites. InputError naming the flag
// for a missing '=', an empty name, a behaviour given twice or requiring itself; which names the
// data has, and circles, are the data's problem's to check (loop::dataset_problem).
std::map<std::string, std::vector<std::string>> parse_requires(
    const std::vector<std::string>& typed) {
  std::map<std::string, std::vector<std::string>> prerequisites;
  for (const std::string& text : typed) {
    const auto fail = [&](const std::string& problem) {
      throw InputError(fmt::format("--requires {}: {}", text, problem));
    };
    const auto equals = text.find('=');
    if (equals == std::string::npos || equals == 0 || equals + 1 == text.size())
      fail("expected BEHAVIOUR=BEHAVIOUR[,BEHAVIOUR...], e.g. squeeze=grasp or shake=grasp,lift");
    const std::string behaviour = text.substr(0, equals);
    std::vector<std::string> needed;
    std::istringstream list(text.substr(equals + 1));
    for (std::string name; std::getline(list, name, ',');) {
      if (name.empty()) fail("an empty behaviour name");
      if (name == behaviour) fail(behaviour + " cannot require itself");
      if (std::find(needed.begin(), needed.end(), name) != needed.end())
        fail(name + " is listed twice");
      needed.push_back(name);
    }
    if (!prerequisites.emplace(behaviour, std::move(needed)).second)
      fail(fmt::format("'{}' is given twice: list all it requires once", behaviour));
  }
  return prerequisites;
}

// The fitting options the user gave, over the defaults (perception::choose_fit_options).
perception::FitOptions fit_options(const TrainFlags& f, const CLI::App& cmd,
                                   perception::DataKind kind) {
  perception::FitChoices c;
  c.series = parse_series_choices(f.series);
  if (given(cmd, "--cross-validation")) c.cross_validation = f.cross_validation;
  if (given(cmd, "--classifier")) c.classifier = f.given.classifier;
  if (given(cmd, "--sample-rate")) c.sample_rate = f.given.analysis.sample_rate;
  if (given(cmd, "--folds")) c.folds = f.given.folds;
  if (given(cmd, "--seed")) c.seed = f.given.seed;
  if (given(cmd, "--reject")) c.reject = f.reject;
  if (given(cmd, "--reject-margin")) c.reject_margin = f.given.reject_margin;
  if (given(cmd, "--alpha")) c.alpha = f.given.dirichlet_alpha;
  if (given(cmd, "--table")) c.table = f.table;
  if (given(cmd, "--fuse")) c.fuse = f.fuse;
  if (given(cmd, "--temper")) c.temper = f.temper;
  // A recordings tree with series has several modalities per behaviour (read before training:
  // listing the tree is cheap).
  bool several = false;
  if (kind == perception::DataKind::recordings)
    for (const auto& r : perception::load_recording_set(f.data).recordings)
      several = several || !r.series.empty();
  return perception::choose_fit_options(c, kind, given(cmd, "--groups") || given(cmd, "--hold-out"),
                                        several);
}

// --problem-out keeps --problem-base when it is named, or for a recordings tree whose classes are
// its objects (cross-validated by performance, the report's setting); else it is the data's own.
bool keeps_problem_base(const TrainFlags& f, const CLI::App& cmd, perception::DataKind kind,
                        const perception::FitOptions& o) {
  const bool base = given(cmd, "--problem-base") ||
                    (kind == perception::DataKind::recordings &&
                     o.cross_validation != perception::CrossValidation::by_session &&
                     !given(cmd, "--groups") && !given(cmd, "--hold-out"));
  if (base)
    for (const char* name :
         {"--reward-right", "--reward-wrong", "--reward-sense", "--costs", "--requires"})
      if (given(cmd, name))
        throw InputError(fmt::format(
            "{} {} the data's own problem, and --problem-out here keeps --problem-base's "
            "actions and rewards ({}): drop --problem-base, or give --groups or --hold-out",
            name, std::string(name) == "--requires" ? "orders the behaviours of" : "prices",
            f.problem_base));
  return base;
}

// The base problem's objects and sensing actions must all have data: said before training.
void check_coverage(const TrainFlags& f, const pomdp::Problem& base,
                    const perception::FeatureSet& set) {
  const auto* object_model = base.model->object_identification();
  if (object_model == nullptr) return;  // calibrate_problem says what is wrong with it
  for (const auto& object : object_model->data().objects)
    if (set.object_index(object) < 0)
      throw InputError(
          f.problem_base, 0,
          fmt::format("object '{}' of the problem has no recordings in {} (objects: {})", object,
                      f.data, fmt::join(set.objects, ", ")));
  for (const auto& action : object_model->data().sensing)
    if (set.action(action.name) == nullptr)
      throw InputError(f.problem_base, 0,
                       fmt::format("sensing action '{}' of the problem has no recordings in {}",
                                   action.name, f.data));
}

perception::FeatureSet load_data(const TrainFlags& f, perception::DataKind kind,
                                 const perception::FitOptions& o) {
  if (kind == perception::DataKind::features) return perception::load_feature_set(f.data);
  const perception::RecordingSet recordings = perception::load_recording_set(f.data);
  spdlog::info("{}: {} recordings, {} objects x {} actions; computing their features", f.data,
               recordings.recordings.size(), recordings.objects.size(), recordings.actions.size());
  return perception::recordings_as_features(recordings, o,
                                            [](const std::string& stage, int done, int total) {
                                              if (done == total || done % 100 == 0)
                                                spdlog::info("{} {}/{}", stage, done, total);
                                            });
}

// Per action: its confusion (for a few classes; a 100 x 100 matrix reads as noise), temperature
// and reject threshold; then each modality's and the combined held-out accuracy.
void print_model(const perception::ObservationModel& model, const perception::FitOptions& o) {
  const std::string how =
      o.cross_validation == perception::CrossValidation::by_session   ? "by session"
      : o.cross_validation == perception::CrossValidation::by_surface ? "each table held out"
      : o.folds == 0                                                  ? "leave-one-out"
                     : fmt::format("{} folds", o.folds);
  for (const std::string& action : model.actions()) {
    const perception::ActionCalibration& c = model.calibration(action);
    if (model.classes().size() <= 10)
      print_confusion(fmt::format("{} (cross-validated, {})", action, how), c.confusion);
    fmt::print("  temperature {:.4g}, reject threshold {:.4g}\n", c.temperature,
               c.reject_threshold);
  }
  fmt::print("held-out accuracy (cross-validated, {}), per behaviour:\n", how);
  for (const std::string& action : model.actions()) {
    const perception::ActionFit& fit = *model.calibration(action).fit;
    const auto& modalities = model.modalities(action);
    std::string text;
    for (std::size_t m = 0; m < modalities.size(); ++m)
      text += fmt::format("{} {:.3f} (weight {:.3g}), ", modalities[m].name,
                          fit.modality_accuracy[m], model.weights(action)[m]);
    fmt::print("  {}: {}combined {:.3f}; table prior strength {:.3g}, temper {:.3g}\n", action,
               text, fit.fused_accuracy, fit.shrinkage_strength, fit.temper);
  }
}

void write_base_problem(const TrainFlags& f, const pomdp::Problem& base,
                        const perception::ObservationModel& model) {
  const auto calibrated = loop::calibrate_problem(base, model, f.problem_out);
  loop::save_problem(
      *calibrated, f.problem_out,
      fmt::format("# Written by: echoplan train --data {} --classifier {}\n# Base problem: {}; "
                  "observation table calibrated from {} (cross-validated, {} table, Dirichlet "
                  "alpha {}).\n",
                  f.data, model.classifier_name(), f.problem_base, f.out,
                  perception::table_estimate_name(model.table_estimate()),
                  model.dirichlet_alpha()));
}

void write_data_problem(const TrainFlags& f, const perception::FeatureSet& set,
                        const perception::DatasetTask& task,
                        const perception::ObservationModel& model) {
  const pomdp::ObjectProblemData data =
      loop::dataset_problem(task, model, f.rewards, loop::default_uses(set));
  std::ostringstream text;
  text << fmt::format(
      "# Written by: echoplan train --data {}{}{}{} --hold-out {} --classifier {}\n"
      "# {} classes, {} bins; observation table: calibrated held-out decisions "
      "(docs/feature-sets.md).\n",
      f.data, f.groups.empty() ? "" : " --groups " + f.groups,
      f.costs.empty() ? "" : " --costs " + f.costs,
      f.prerequisites.empty()
          ? ""
          : fmt::format(" --requires {}", fmt::join(f.prerequisites, " --requires ")),
      hold_out_name(task.hold_out), model.classifier_name(), task.classes.size(), task.bins.size());
  pomdp::BeliefSettings belief;
  belief.type = pomdp::BeliefSettings::Type::exact;  // a few classes: exact beliefs are cheap
  pomdp::write_problem_yaml(text, data, belief, pomdp::PlannerDefaults{});
  write_file_atomically(f.problem_out, text.str());
}

void train(TrainFlags f, const CLI::App& cmd) {
  if (f.problem_out.empty() && f.out.empty())
    throw InputError("give --out (the model file) or --problem-out (the problem), or both");
  const perception::DataKind kind = perception::data_kind(f.data);
  const perception::FitOptions o = fit_options(f, cmd, kind);
  const bool base_problem = keeps_problem_base(f, cmd, kind, o);
  const perception::HoldOut hold_out =
      perception::parse_hold_out(f.hold_out.empty() ? "session" : f.hold_out);
  // Read the base problem and the groups first: a wrong path should fail before minutes of work.
  std::optional<pomdp::Problem> base;
  if (base_problem && !f.problem_out.empty()) base = pomdp::load_problem(f.problem_base);
  std::optional<perception::ObjectGroups> groups;
  if (!f.groups.empty()) groups = perception::load_groups(f.groups);
  f.rewards.prerequisites = parse_requires(f.prerequisites);
  const perception::FeatureSet set = load_data(f, kind, o);
  if (base) check_coverage(f, *base, set);
  if (!f.costs.empty()) {
    std::vector<std::string> behaviours;
    for (const perception::ActionData& action : set.actions) behaviours.push_back(action.name);
    f.rewards.costs = loop::load_behaviour_costs(f.costs, behaviours);
  }
  const perception::DatasetTask task =
      perception::make_dataset_task(set, groups ? &*groups : nullptr, hold_out, f.groups);
  // Names the data lacks and circles in --requires are said before the fit.
  if (!base_problem && !f.rewards.prerequisites.empty()) {
    try {
      loop::dataset_problem_shape(task, set, f.rewards);
    } catch (const InputError& e) {
      throw InputError("--" + e.problem());
    }
  }
  spdlog::info("{}: {} objects, {} sessions, {} behaviours; {} classes, {} bins; classifier {}",
               f.data, set.objects.size(), set.sessions.size(), set.actions.size(),
               task.classes.size(), task.bins.size(), o.classifier);
  std::vector<int> all(set.sessions.size());
  std::iota(all.begin(), all.end(), 0);
  const perception::ObservationModel model = perception::fit_observation_model(
      set, task, all, o, [](const std::string& stage, int done, int total) {
        spdlog::info("{} {}/{} behaviours", stage, done, total);
      });
  print_model(model, o);
  if (!f.out.empty()) {
    perception::save_observation_model(model, f.out);
    fmt::print("model: {}\n", f.out);
  }
  if (f.problem_out.empty()) return;
  if (base)
    write_base_problem(f, *base, model);
  else
    write_data_problem(f, set, task, model);
  fmt::print("problem: {}\n", f.problem_out);
}

void add_task_options(CLI::App& cmd, TrainFlags& f) {
  cmd.add_option("--groups", f.groups,
                 "Groups file (object,group): sort into the groups (and, with --hold-out object, "
                 "recognise them)");
  cmd.add_option("--hold-out", f.hold_out,
                 "What a trial is: 'session' (a new session of a known object: classes are the "
                 "objects; default) or 'object' (a novel object: classes are the groups)");
  cmd.add_option("--reward-right", f.rewards.right, "The data's problem: reward of the right bin")
      ->capture_default_str();
  cmd.add_option("--reward-wrong", f.rewards.wrong, "The data's problem: reward of a wrong bin")
      ->capture_default_str();
  cmd.add_option("--reward-sense", f.rewards.sense,
                 "The data's problem: reward of each behaviour not priced by --costs")
      ->capture_default_str();
  cmd.add_option("--costs", f.costs,
                 "The data's problem: CSV file 'behaviour,cost', a row per priced behaviour: each "
                 "performance of it earns -cost (the others --reward-sense)");
  cmd.add_option("--requires", f.prerequisites,
                 "The data's problem: BEHAVIOUR=B1[,B2...] (repeatable): BEHAVIOUR can be "
                 "performed only after each of B1, B2, ... has been (e.g. shake=grasp, as on an "
                 "arm that must hold an object to shake it)");
}

void add_fit_options(CLI::App& cmd, TrainFlags& f) {
  const perception::FitOptions clips;
  const perception::FitOptions sessions = perception::session_fit_options();
  cmd.add_option("--cross-validation", f.cross_validation,
                 "'performance' (leave-one-out or --folds; the default for a recordings tree) or "
                 "'session' (the task's folds over sessions; the default for a feature set or with "
                 "--groups or --hold-out), or 'surface' (a recordings tree made on several tables, "
                 "its manifest's `surface` column: each table held out in turn, so the table says "
                 "what a table never heard does; the defaults of 'performance'). The defaults "
                 "below follow it: performance | session")
      ->check(CLI::IsMember(std::vector<std::string>{"performance", "session", "surface"}));
  std::vector<std::string> accepted = perception::classifier_names();
  for (const auto& [old_name, name] : perception::classifier_aliases())
    accepted.push_back(old_name);
  for (const std::string& name : perception::row_classifier_names()) accepted.push_back(name);
  cmd.add_option("--classifier,--feature-classifier", f.given.classifier,
                 fmt::format("An audio preset ({}: it computes a recordings tree's rows) or a row "
                             "classifier ({}). Default: {} | {}",
                             fmt::join(perception::classifier_names(), ", "),
                             fmt::join(perception::row_classifier_names(), ", "), clips.classifier,
                             sessions.classifier))
      ->check(CLI::IsMember(accepted));
  add_series_option(cmd, f.series);
  cmd.add_option("--sample-rate", f.given.analysis.sample_rate,
                 fmt::format("Rate (Hz) every recording is resampled to. Default: {}",
                             clips.analysis.sample_rate));
  cmd.add_option("--folds", f.given.folds,
                 "By performance: cross-validation folds, stratified by class (0 = leave-one-out; "
                 "default)");
  cmd.add_option("--seed", f.given.seed, "By performance: seed of the fold assignment (--folds)");
  cmd.add_flag("--reject,!--no-reject", f.reject,
               "Add the `unknown` symbol for performances unlike any class (one modality per "
               "behaviour). Default: on | off");
  cmd.add_option("--reject-margin", f.given.reject_margin,
                 fmt::format("Unknown beyond this many times the largest held-out distance of a "
                             "correctly classified performance. Default: {}",
                             clips.reject_margin));
  cmd.add_option("--alpha", f.given.dirichlet_alpha,
                 fmt::format("Counts and soft tables: Dirichlet pseudo-count added to each cell. "
                             "Default: {} | {}",
                             clips.dirichlet_alpha, sessions.dirichlet_alpha));
  cmd.add_option(
         "--table", f.table,
         "Observation table from the held-out decisions: 'counts' (one per performance), "
         "'soft' (each adds its calibrated probabilities: narrow wins give softer rows) or "
         "'shrunk' (counts shrunk towards a pooled structure of the bins: many classes, few "
         "rows each). Default: counts | shrunk")
      ->check(CLI::IsMember(perception::table_estimate_names()));
  cmd.add_flag("--fuse,!--no-fuse", f.fuse,
               "Weigh the modalities by fitted fusion weights (else one temperature on their "
               "summed scores). Default: off | on");
  cmd.add_flag("--temper,!--no-temper", f.temper,
               "By session: temper the tables for a session's correlated repeats. Default: off | "
               "on");
}

}  // namespace

void add_train_command(CLI::App& app) {
  auto f = std::make_shared<TrainFlags>();
  auto* cmd = app.add_subcommand(
      "train",
      R"(Fit the observation model on DIR, a recordings tree DIR/<object>/<action>/*.wav (with
DIR/manifest.csv if present) or a feature set DIR/<action>/<modality>.csv; print what
cross-validation measured; write the model (--out) and, when asked, the problem that plans with
its calibrated table (--problem-out). The model runs wherever it was measured: `echoplan run
--model`, a campaign's `world.model`, the ROS observation node. One pipeline for every kind of data
(docs/feature-sets.md): a classifier per behaviour and modality, cross-validated by performance or
by session, calibrated into probabilities, grades and a table. Where two defaults are shown
("A | B"), A is by performance and B by session.
Examples:
  echoplan train --data recordings --out model.json --problem-out problems/calibrated.yaml
  echoplan train --data features --groups features/groups.csv --hold-out object --out model.json --problem-out dataset.yaml)");
  cmd->add_option("--data", f->data,
                  "Folder of recordings (e.g. written by `echoplan dataset`) "
                  "or a feature set")
      ->required();
  cmd->add_option("-o,--out", f->out, "Model file to write (JSON; one format for all data)");
  cmd->add_option("--problem-out", f->problem_out,
                  "Also write this problem file (YAML): --problem-base with the calibrated table "
                  "(a recordings tree by performance, or --problem-base named), else the data's "
                  "problem (classes, behaviours with use limits, bins, rewards, table)");
  cmd->add_option(
         "--problem-base", f->problem_base,
         "Problem whose objects, actions, rewards and planner settings --problem-out keeps")
      ->capture_default_str();
  add_task_options(*cmd, *f);
  add_fit_options(*cmd, *f);
  cmd->callback([f, cmd] { train(*f, *cmd); });
}

}  // namespace echoplan::cli
