// `echoplan train`: fit the observation model on a folder of recordings, report its cross-validated
// confusion, save it as JSON and, optionally, write a problem file that plans with the calibrated
// table. Without --out, the data is a dataset (a feature set or a recordings tree) and train writes
// its problem (train_dataset.cpp).
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
#include "perception/recording_set.h"
#include "pomdp/problem.h"

namespace echoplan::cli {
namespace {

struct TrainFlags {
  DatasetTrainFlags dataset;
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

void train(TrainFlags f) {
  if (f.out.empty()) {
    f.dataset.data = f.data;
    f.dataset.problem_out = f.problem_out;
    train_dataset(f.dataset);
    return;
  }
  if (!f.dataset.groups.empty() || !f.dataset.hold_out.empty())
    throw InputError(
        "--groups and --hold-out are for datasets: leave out --out (which saves an "
        "audio model of recordings) and give --problem-out");
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

}  // namespace

void add_train_command(CLI::App& app) {
  auto opt = std::make_shared<TrainFlags>();
  auto* cmd = app.add_subcommand(
      "train",
      "With --out: fit the observation model on recordings DIR/<object>/<action>/*.wav (and "
      "DIR/manifest.csv if present):\n"
      "one classifier per action, cross-validated; prints accuracy and confusion per action and "
      "saves the model\n"
      "(JSON) with the calibrated table P(heard | object, action).\n"
      "Example: echoplan train --data recordings --out model.json --problem-out "
      "problems/calibrated.yaml\n"
      "Without --out: DIR is a dataset, a feature set DIR/<action>/<modality>.csv or a recordings "
      "tree; fits a fused,\n"
      "calibrated model on all of it (docs/feature-sets.md), prints each behaviour's held-out "
      "accuracy per modality\n"
      "and fused, and writes --problem-out: the classes, one sensing action per behaviour with "
      "its use limit,\n"
      "the sorting actions and rewards, and the calibrated table.\n"
      "Example: echoplan train --data features --groups features/groups.csv --hold-out object "
      "--problem-out dataset.yaml");
  cmd->add_option("--data", opt->data,
                  "Folder of recordings (e.g. written by `echoplan dataset`), or without --out a "
                  "feature set")
      ->required();
  cmd->add_option("-o,--out", opt->out,
                  "Model file to write (JSON); without it, DIR is trained as a dataset");
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
  cmd->add_option("--classifier", opt->train.classifier,
                  "Classifier: " + names + " (old names still accepted: " + aliases + ")")
      ->check(CLI::IsMember(accepted))
      ->capture_default_str();
  cmd->add_option("--sample-rate", opt->train.analysis.sample_rate,
                  "Rate (Hz) every recording is resampled to")
      ->capture_default_str();
  cmd->add_flag("--no-reject", opt->no_reject, "Always report a class (no `unknown` symbol)");
  cmd->add_option("--reject-margin", opt->train.reject_margin,
                  "Unknown beyond this many times the largest held-out distance of a correctly "
                  "classified recording")
      ->capture_default_str();
  cmd->add_option("--alpha", opt->train.dirichlet_alpha,
                  "Dirichlet pseudo-count added to each confusion cell")
      ->capture_default_str();
  opt->table = perception::table_estimate_name(opt->train.table);
  cmd->add_option("--table", opt->table,
                  "Observation table from the held-out decisions: 'counts' (one count per clip "
                  "for the class it was given) or 'soft' (each clip adds its calibrated class "
                  "probabilities: narrow wins give softer rows)")
      ->check(CLI::IsMember(perception::table_estimate_names()))
      ->capture_default_str();
  cmd->add_option("--folds", opt->train.folds, "Cross-validation folds (0 = leave-one-out)")
      ->capture_default_str();
  cmd->add_option("--seed", opt->train.seed, "Seed of the fold assignment (with --folds)")
      ->capture_default_str();
  cmd->add_option(
      "--problem-out", opt->problem_out,
      "Also write this problem file (YAML): --problem-base with the calibrated observation table");
  cmd->add_option(
         "--problem-base", opt->problem_base,
         "Problem whose objects, actions, rewards and planner settings --problem-out keeps")
      ->capture_default_str();
  cmd->callback([opt] { train(*opt); });
}

}  // namespace echoplan::cli
