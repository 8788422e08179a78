#include "commands/train_dataset.h"

#include <fmt/core.h>
#include <fmt/ranges.h>
#include <spdlog/spdlog.h>

#include <numeric>
#include <optional>
#include <sstream>

#include "common/error.h"
#include "common/file_io.h"
#include "loop/behaviour_costs.h"
#include "perception/dataset_task.h"
#include "perception/feature_model.h"
#include "perception/observation_model_json.h"
#include "perception/recording_features.h"
#include "perception/row_classifier.h"
#include "pomdp/problem.h"

namespace echoplan::cli {
namespace {
perception::FeatureSet load_data(const std::string& dir) {
  if (perception::data_kind(dir) == perception::DataKind::recordings)
    spdlog::info("{}: a recordings tree; computing its audio features", dir);
  return perception::load_data(dir, [](const std::string& stage, int done, int total) {
    if (done == total || done % 100 == 0) spdlog::info("{} {}/{}", stage, done, total);
  });
}

void print_fits(const perception::ObservationModel& model) {
  fmt::print("held-out accuracy (inner cross-validation), per behaviour:\n");
  for (const std::string& action : model.actions()) {
    const perception::ActionFit& fit = *model.calibration(action).fit;
    const auto& modalities = model.modalities(action);
    std::string text;
    for (std::size_t m = 0; m < modalities.size(); ++m)
      text += fmt::format("{} {:.3f} (weight {:.3g}), ", modalities[m].name,
                          fit.modality_accuracy[m], model.weights(action)[m]);
    fmt::print("  {}: {}fused {:.3f}; table prior strength {:.3g}, temper {:.3g}\n", action, text,
               fit.fused_accuracy, fit.shrinkage_strength, fit.temper);
  }
}

void write_problem(const DatasetTrainFlags& f, const pomdp::ObjectProblemData& data,
                   const perception::DatasetTask& task) {
  std::ostringstream text;
  text << fmt::format(
      "# Written by: echoplan train --data {}{}{} --hold-out {} --feature-classifier {}\n"
      "# {} classes, {} bins; observation table: fused, calibrated held-out decisions "
      "(docs/feature-sets.md).\n",
      f.data, f.groups.empty() ? "" : " --groups " + f.groups,
      f.costs.empty() ? "" : " --costs " + f.costs, hold_out_name(task.hold_out), f.classifier,
      task.classes.size(), task.bins.size());
  pomdp::BeliefSettings belief;
  belief.type = pomdp::BeliefSettings::Type::exact;  // a few classes: exact beliefs are cheap
  pomdp::write_problem_yaml(text, data, belief, pomdp::PlannerDefaults{});
  write_file_atomically(f.problem_out, text.str());
}

}  // namespace

void add_dataset_train_options(CLI::App& cmd, DatasetTrainFlags& flags) {
  cmd.add_option("--groups", flags.groups,
                 "Sessions: groups file (object,group): sort into the groups (and, with --hold-out "
                 "object, recognise them)");
  cmd.add_option("--hold-out", flags.hold_out,
                 "Sessions: what a trial is, 'session' (a new session of a known object: classes "
                 "are the objects; default) or 'object' (a novel object: classes are the groups)");
  cmd.add_option("--feature-classifier", flags.classifier,
                 "Sessions: row classifier per behaviour and modality (" +
                     fmt::format("{}", fmt::join(perception::row_classifier_names(), ", ")) + ")")
      ->capture_default_str();
  cmd.add_option("--reward-right", flags.rewards.right, "Sessions: reward of the right bin")
      ->capture_default_str();
  cmd.add_option("--reward-wrong", flags.rewards.wrong, "Sessions: reward of a wrong bin")
      ->capture_default_str();
  cmd.add_option("--reward-sense", flags.rewards.sense,
                 "Sessions: reward of each behaviour not priced by --costs")
      ->capture_default_str();
  cmd.add_option("--costs", flags.costs,
                 "Sessions: CSV file 'behaviour,cost', a row per priced behaviour: each "
                 "performance of it earns -cost (the others --reward-sense)");
}

void train_dataset(DatasetTrainFlags f) {
  if (f.problem_out.empty() && f.out.empty())
    throw InputError("give --out (the model file) or --problem-out (the problem), or both");
  const perception::HoldOut hold_out =
      perception::parse_hold_out(f.hold_out.empty() ? "session" : f.hold_out);
  perception::make_row_classifier(f.classifier);  // a bad name fails before loading
  std::optional<perception::ObjectGroups> groups;
  if (!f.groups.empty()) groups = perception::load_groups(f.groups);
  const perception::FeatureSet set = load_data(f.data);
  if (!f.costs.empty()) {
    std::vector<std::string> behaviours;
    for (const perception::ActionData& action : set.actions) behaviours.push_back(action.name);
    f.rewards.costs = loop::load_behaviour_costs(f.costs, behaviours);
  }
  const perception::DatasetTask task =
      perception::make_dataset_task(set, groups ? &*groups : nullptr, hold_out, f.groups);
  spdlog::info("{}: {} objects, {} sessions, {} behaviours; {} classes, {} bins", f.data,
               set.objects.size(), set.sessions.size(), set.actions.size(), task.classes.size(),
               task.bins.size());
  std::vector<int> all(set.sessions.size());
  std::iota(all.begin(), all.end(), 0);
  const perception::ObservationModel model = perception::fit_feature_model(
      set, task, all, {f.classifier}, [](const std::string& stage, int done, int total) {
        spdlog::info("{} {}/{} behaviours", stage, done, total);
      });
  print_fits(model);
  if (!f.out.empty()) {
    perception::save_observation_model(model, f.out);
    fmt::print("model: {}\n", f.out);
  }
  if (f.problem_out.empty()) return;
  const std::vector<int> uses = loop::default_uses(set);
  write_problem(f, loop::dataset_problem(task, model, f.rewards, uses), task);
  fmt::print("problem: {}\n", f.problem_out);
}

}  // namespace echoplan::cli
