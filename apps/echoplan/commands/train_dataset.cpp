#include "commands/train_dataset.h"

#include <fmt/core.h>
#include <spdlog/spdlog.h>

#include <filesystem>
#include <numeric>
#include <optional>
#include <sstream>

#include "common/error.h"
#include "common/file_io.h"
#include "perception/dataset_task.h"
#include "perception/feature_classifier.h"
#include "perception/feature_model.h"
#include "perception/recording_features.h"
#include "perception/recording_set.h"
#include "pomdp/problem.h"

namespace echoplan::cli {
namespace {
namespace fs = std::filesystem;

// A feature set has .csv files one level down (DIR/<action>/<modality>.csv); a recordings tree
// has audio two levels down (DIR/<object>/<action>/*.wav).
bool is_feature_set(const std::string& dir) {
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) throw InputError(dir, 0, "--data: not a folder");
  for (const fs::path& entry : visible_entries(dir))
    if (fs::is_directory(entry))
      for (const fs::path& file : visible_entries(entry))
        if (fs::is_regular_file(file) && file.extension() == ".csv") return true;
  return false;
}

perception::FeatureSet load_data(const std::string& dir) {
  if (is_feature_set(dir)) return perception::load_feature_set(dir);
  spdlog::info("{}: a recordings tree; computing its audio features", dir);
  const perception::RecordingSet recordings = perception::load_recording_set(dir);
  return perception::feature_set_from_recordings(recordings, {},
                                                 [](const std::string& stage, int done, int total) {
                                                   if (done == total || done % 100 == 0)
                                                     spdlog::info("{} {}/{}", stage, done, total);
                                                 });
}

void print_fits(const perception::FeatureModel& model) {
  fmt::print("held-out accuracy (inner cross-validation), per behaviour:\n");
  for (const perception::ActionFit& fit : model.fits()) {
    std::string modalities;
    for (std::size_t m = 0; m < fit.modalities.size(); ++m)
      modalities += fmt::format("{} {:.3f} (weight {:.3g}), ", fit.modalities[m],
                                fit.modality_accuracy[m], fit.weights[m]);
    fmt::print("  {}: {}fused {:.3f}; table prior strength {:.3g}, temper {:.3g}\n", fit.action,
               modalities, fit.fused_accuracy, fit.shrinkage_strength, fit.temper);
  }
}

void write_problem(const DatasetTrainFlags& f, const pomdp::ObjectProblemData& data,
                   const perception::DatasetTask& task) {
  std::ostringstream text;
  text << fmt::format(
      "# Written by: echoplan train --data {}{} --hold-out {} --feature-classifier {}\n"
      "# {} classes, {} bins; observation table: fused, calibrated held-out decisions "
      "(docs/feature-sets.md).\n",
      f.data, f.groups.empty() ? "" : " --groups " + f.groups, hold_out_name(task.hold_out),
      f.classifier, task.classes.size(), task.bins.size());
  pomdp::BeliefSettings belief;
  belief.type = pomdp::BeliefSettings::Type::exact;  // a few classes: exact beliefs are cheap
  pomdp::write_problem_yaml(text, data, belief, pomdp::PlannerDefaults{});
  write_file_atomically(f.problem_out, text.str());
}

}  // namespace

void add_dataset_train_options(CLI::App& cmd, DatasetTrainFlags& flags) {
  cmd.add_option("--groups", flags.groups,
                 "Dataset: groups file (object,group): sort into the groups (and, with --hold-out "
                 "object, recognise them)");
  cmd.add_option("--hold-out", flags.hold_out,
                 "Dataset: what a trial is, 'session' (a new session of a known object: classes "
                 "are the objects; default) or 'object' (a novel object: classes are the groups)");
  cmd.add_option("--feature-classifier", flags.classifier,
                 "Dataset: classifier per behaviour and modality (lda, nearest-neighbour)")
      ->capture_default_str();
  cmd.add_option("--reward-right", flags.rewards.right, "Dataset: reward of the right bin")
      ->capture_default_str();
  cmd.add_option("--reward-wrong", flags.rewards.wrong, "Dataset: reward of a wrong bin")
      ->capture_default_str();
  cmd.add_option("--reward-sense", flags.rewards.sense, "Dataset: reward of each behaviour")
      ->capture_default_str();
}

void train_dataset(const DatasetTrainFlags& f) {
  if (f.problem_out.empty())
    throw InputError("--problem-out is required for a dataset (or give --out for recordings)");
  const perception::HoldOut hold_out =
      perception::parse_hold_out(f.hold_out.empty() ? "session" : f.hold_out);
  perception::make_feature_classifier(f.classifier);  // a bad name fails before loading
  std::optional<perception::ObjectGroups> groups;
  if (!f.groups.empty()) groups = perception::load_groups(f.groups);
  const perception::FeatureSet set = load_data(f.data);
  const perception::DatasetTask task =
      perception::make_dataset_task(set, groups ? &*groups : nullptr, hold_out, f.groups);
  spdlog::info("{}: {} objects, {} sessions, {} behaviours; {} classes, {} bins", f.data,
               set.objects.size(), set.sessions.size(), set.actions.size(), task.classes.size(),
               task.bins.size());
  std::vector<int> all(set.sessions.size());
  std::iota(all.begin(), all.end(), 0);
  const perception::FeatureModel model = perception::fit_feature_model(
      set, task, all, {f.classifier}, [](const std::string& stage, int done, int total) {
        spdlog::info("{} {}/{} behaviours", stage, done, total);
      });
  print_fits(model);
  const std::vector<int> uses = loop::default_uses(set);
  write_problem(f, loop::dataset_problem(task, model, f.rewards, uses), task);
  fmt::print("problem: {}\n", f.problem_out);
}

}  // namespace echoplan::cli
