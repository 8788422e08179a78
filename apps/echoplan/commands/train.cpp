// `echoplan train`: fit the one observation model on a data folder (a recordings tree or a feature
// set), report what cross-validation measured, save the model file and, when asked, the problem
// that plans with its calibrated table. Two recipes, chosen by what the user asks for:
//   clips     each recording a unit of cross-validation: an audio classifier per action, the
//             reject option, a counts or soft table, --problem-out from --problem-base (this file);
//   sessions  each session a unit: any modalities fused, the table shrunk and tempered, classes
//             the objects or (--groups, --hold-out object) their groups, --problem-out a
//             dataset problem (train_dataset.cpp).
#include <fmt/core.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <optional>
#include <stdexcept>

#include "commands/commands.h"
#include "commands/perception_report.h"
#include "commands/train_dataset.h"
#include "common/error.h"
#include "loop/calibrated_problem.h"
#include "perception/classifier.h"
#include "perception/observation_model.h"
#include "perception/recording_features.h"
#include "perception/recording_set.h"
#include "pomdp/problem.h"

namespace echoplan::cli {
namespace {

struct TrainFlags {
  DatasetTrainFlags dataset;
  std::string recipe;  // "clips", "sessions", or empty: chosen by choose_recipe
  std::string data;
  std::string out;
  std::string problem_out;
  std::string problem_base = "problems/audio_objects.yaml";
  bool no_reject = false;
  std::string table;
  perception::TrainOptions train;
};

// The problem's objects and sensing actions must all have recordings: said before training.
void check_coverage(const TrainFlags& f, const pomdp::Problem& base,
                    const perception::RecordingSet& set) {
  const auto* object_model = base.model->object_identification();
  if (object_model == nullptr) return;  // calibrate_problem says what is wrong with it
  for (const auto& object : object_model->data().objects)
    if (set.object_index(object) < 0)
      throw InputError(
          f.problem_base, 0,
          fmt::format("object '{}' of the problem has no recordings in {} (objects: {})", object,
                      f.data, fmt::join(set.objects, ", ")));
  for (const auto& action : object_model->data().sensing)
    if (std::find(set.actions.begin(), set.actions.end(), action.name) == set.actions.end())
      throw InputError(
          f.problem_base, 0,
          fmt::format("sensing action '{}' of the problem has no recordings in {} (actions: {})",
                      action.name, f.data, fmt::join(set.actions, ", ")));
}

void print_calibration(const TrainFlags& f, const perception::ObservationModel& model) {
  for (const auto& action : model.actions()) {
    const auto& c = model.calibration(action);
    print_confusion(
        fmt::format("{} (cross-validated, {})", action,
                    f.train.folds == 0 ? "leave-one-out" : fmt::format("{} folds", f.train.folds)),
        c.confusion);
    fmt::print("  temperature {:.4g}, reject threshold {:.4g}\n", c.temperature,
               c.reject_threshold);
  }
}

// The options only one recipe reads, for the error that names them.
const std::vector<std::string>& clips_only() {
  static const std::vector<std::string> names{"--classifier",    "--sample-rate", "--no-reject",
                                              "--reject-margin", "--alpha",       "--table",
                                              "--folds",         "--seed",        "--problem-base"};
  return names;
}
const std::vector<std::string>& sessions_only() {
  static const std::vector<std::string> names{
      "--groups",       "--hold-out", "--feature-classifier", "--reward-right", "--reward-wrong",
      "--reward-sense", "--costs"};
  return names;
}

// --recipe when given; else sessions for a feature set, for options only sessions read, or without
// --out (the problem-only form, as before --out existed for it); else clips.
std::string choose_recipe(const TrainFlags& f, const CLI::App& cmd) {
  if (!f.recipe.empty()) return f.recipe;
  for (const std::string& name : sessions_only())
    if (cmd.count(name) > 0) return "sessions";
  if (f.out.empty()) return "sessions";
  return perception::data_kind(f.data) == perception::DataKind::features ? "sessions" : "clips";
}

// An option of the other recipe is a mistake worth saying, not ignoring.
void check_recipe_options(const std::string& recipe, const CLI::App& cmd) {
  for (const std::string& name : recipe == "clips" ? sessions_only() : clips_only())
    if (cmd.count(name) > 0)
      throw InputError(fmt::format(
          "{} is an option of the {} recipe, and this training is the {} recipe ({})", name,
          recipe == "clips" ? "sessions" : "clips", recipe,
          recipe == "clips" ? "a recordings tree, each clip a unit"
                            : "each session a unit: a feature set, --groups or --hold-out"));
}

void train_clips(TrainFlags f) {
  if (f.out.empty()) throw InputError("--out is required: the clips recipe writes a model file");
  f.train.reject = !f.no_reject;
  f.train.table = perception::parse_table_estimate(f.table);
  // Read the base problem first: a wrong path should fail before minutes of training.
  std::optional<pomdp::Problem> base;
  if (!f.problem_out.empty()) base = pomdp::load_problem(f.problem_base);
  const perception::RecordingSet set = perception::load_recording_set(f.data);
  if (base) check_coverage(f, *base, set);
  spdlog::info("{} recordings: {} objects x {} actions; classifier {}", set.recordings.size(),
               set.objects.size(), set.actions.size(), f.train.classifier);
  const perception::ObservationModel model = perception::train_observation_model(
      set, f.train, [](const std::string& stage, int done, int total) {
        if (done == total || done % 20 == 0) spdlog::info("{} {}/{}", stage, done, total);
      });
  print_calibration(f, model);
  perception::save_observation_model(model, f.out);
  fmt::print("model: {}\n", f.out);
  if (!base) return;
  const auto calibrated = loop::calibrate_problem(*base, model, f.problem_out);
  loop::save_problem(
      *calibrated, f.problem_out,
      fmt::format("# Written by: echoplan train --data {} --classifier {}\n# Base problem: {}; "
                  "observation table calibrated from {} (cross-validated, {} table, Dirichlet "
                  "alpha {}).\n",
                  f.data, f.train.classifier, f.problem_base, f.out,
                  perception::table_estimate_name(f.train.table), f.train.dirichlet_alpha));
  fmt::print("problem: {}\n", f.problem_out);
}

void train(TrainFlags f, const CLI::App& cmd) {
  const std::string recipe = choose_recipe(f, cmd);
  check_recipe_options(recipe, cmd);
  if (recipe == "clips") return train_clips(std::move(f));
  f.dataset.data = f.data;
  f.dataset.out = f.out;
  f.dataset.problem_out = f.problem_out;
  train_dataset(f.dataset);
}

}  // namespace

void add_train_command(CLI::App& app) {
  auto opt = std::make_shared<TrainFlags>();
  auto* cmd = app.add_subcommand(
      "train",
      R"(Fit the observation model on DIR, a recordings tree DIR/<object>/<action>/*.wav (with
DIR/manifest.csv if present) or a feature set DIR/<action>/<modality>.csv; print what
cross-validation measured; write the model (--out) and, when asked, the problem that plans with
its calibrated table (--problem-out). The model runs wherever it was measured: `echoplan run
--model`, a campaign's `world.model`, the ROS observation node. Two recipes (--recipe):
  clips     each recording a unit of cross-validation: one audio classifier per action
            (--classifier), the reject option, a counts or soft table; --problem-out keeps
            --problem-base with the table replaced. The default for a recordings tree.
  sessions  each session a unit (docs/feature-sets.md): every modality classified and fused, the
            table shrunk and tempered for repeats; classes are the objects, or their groups
            (--groups, --hold-out object); --problem-out is the data's problem. The default for a
            feature set, or when --groups or --hold-out is given.
Examples:
  echoplan train --data recordings --out model.json --problem-out problems/calibrated.yaml
  echoplan train --data features --groups features/groups.csv --hold-out object --out model.json --problem-out dataset.yaml)");
  cmd->add_option("--data", opt->data,
                  "Folder of recordings (e.g. written by `echoplan "
                  "dataset`) or a feature set")
      ->required();
  cmd->add_option("-o,--out", opt->out,
                  "Model file to write (JSON; one format for every recipe and data)");
  cmd->add_option("--recipe", opt->recipe,
                  "clips or sessions (default: sessions for a feature set or with --groups or "
                  "--hold-out, else clips)")
      ->check(CLI::IsMember(std::vector<std::string>{"clips", "sessions"}));
  add_dataset_train_options(*cmd, opt->dataset);
  std::string names;
  for (const auto& n : perception::classifier_names()) names += (names.empty() ? "" : ", ") + n;
  // Old names are accepted too (make_classifier maps them); the help lists the current ones.
  std::vector<std::string> accepted = perception::classifier_names();
  std::string aliases;
  for (const auto& [old_name, name] : perception::classifier_aliases()) {
    accepted.push_back(old_name);
    aliases += fmt::format("{}{} for {}", aliases.empty() ? "" : ", ", old_name, name);
  }
  cmd->add_option(
         "--classifier", opt->train.classifier,
         "Clips: audio classifier: " + names + " (old names still accepted: " + aliases + ")")
      ->check(CLI::IsMember(accepted))
      ->capture_default_str();
  cmd->add_option("--sample-rate", opt->train.analysis.sample_rate,
                  "Clips: rate (Hz) every recording is resampled to")
      ->capture_default_str();
  cmd->add_flag("--no-reject", opt->no_reject,
                "Clips: always report a class (no `unknown` symbol)");
  cmd->add_option(
         "--reject-margin", opt->train.reject_margin,
         "Clips: unknown beyond this many times the largest held-out distance of a correctly "
         "classified recording")
      ->capture_default_str();
  cmd->add_option("--alpha", opt->train.dirichlet_alpha,
                  "Clips: Dirichlet pseudo-count added to each confusion cell")
      ->capture_default_str();
  opt->table = perception::table_estimate_name(opt->train.table);
  cmd->add_option(
         "--table", opt->table,
         "Clips: observation table from the held-out decisions: 'counts' (one count per clip "
         "for the class it was given) or 'soft' (each clip adds its calibrated class "
         "probabilities: narrow wins give softer rows)")
      ->check(CLI::IsMember(perception::clip_table_estimate_names()))
      ->capture_default_str();
  cmd->add_option("--folds", opt->train.folds, "Clips: cross-validation folds (0 = leave-one-out)")
      ->capture_default_str();
  cmd->add_option("--seed", opt->train.seed, "Clips: seed of the fold assignment (with --folds)")
      ->capture_default_str();
  cmd->add_option(
      "--problem-out", opt->problem_out,
      "Also write this problem file (YAML): clips, --problem-base with the calibrated table; "
      "sessions, the data's problem (classes, behaviours with use limits, bins, rewards, table)");
  cmd->add_option(
         "--problem-base", opt->problem_base,
         "Clips: problem whose objects, actions, rewards and planner settings --problem-out keeps")
      ->capture_default_str();
  cmd->callback([opt, cmd] { train(*opt, *cmd); });
}

}  // namespace echoplan::cli
