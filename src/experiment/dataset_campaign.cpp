#include "experiment/dataset_campaign.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <map>
#include <set>
#include <sstream>
#include <tuple>

#include "common/error.h"
#include "common/file_io.h"
#include "experiment/campaign_noise.h"
#include "experiment/unheard_choice.h"
#include "loop/dataset_problem.h"
#include "loop/dataset_world.h"
#include "loop/loop.h"
#include "perception/observation_model_json.h"
#include "perception/recording_features.h"

namespace echoplan::experiment {

namespace {

pomdp::Problem dataset_problem_file(pomdp::ObjectProblemData data, const std::string& source) {
  pomdp::Problem problem;
  problem.model = std::make_shared<const pomdp::ObjectIdentificationModel>(std::move(data));
  // The classes are few enough to track exactly; the planner samples its particles from it.
  problem.belief.type = pomdp::BeliefSettings::Type::exact;
  problem.source_path = source;
  return problem;
}

// The sessions of object `object`, in the data's order.
std::vector<int> sessions_of(const perception::FeatureSet& data, int object) {
  std::vector<int> sessions;
  for (std::size_t s = 0; s < data.sessions.size(); ++s)
    if (data.sessions[s].object == object) sessions.push_back(static_cast<int>(s));
  return sessions;
}

// A trial's fold is held out, and the fold's calibration cross-validates what is left, so each
// class needs three objects (hold_out: object) or each object three sessions (hold_out: session).
void check_enough_for_folds(const perception::FeatureSet& data, const perception::DatasetTask& task,
                            const std::string& source) {
  const bool by_object = task.hold_out == perception::HoldOut::object;
  std::vector<int> count(by_object ? task.classes.size() : data.objects.size(), 0);
  if (by_object)
    for (int c : task.class_of_object) ++count.at(c);
  else
    for (const perception::Session& s : data.sessions) ++count.at(s.object);
  for (std::size_t i = 0; i < count.size(); ++i)
    if (count[i] < 3)
      throw InputError(
          source, 0,
          by_object
              ? fmt::format("class '{}' has {} object(s); hold_out: object needs at least 3 per "
                            "class (one held out per trial, two left to calibrate on)",
                            task.classes[i], count[i])
              : fmt::format("object '{}' has {} session(s); hold_out: session needs at least 3 "
                            "per object (one held out per trial, two left to calibrate on)",
                            data.objects[i], count[i]));
}

// A frozen model: one "fold" holding every session, its model the file's (checked against the
// task's classes and the data's actions and modalities before any trial).
void open_frozen_model(DatasetFolds& t, const std::string& path, InputFiles& files) {
  auto model = std::make_shared<const perception::ObservationModel>(
      perception::parse_observation_model(files.text(path), path));
  if (model->classes() != t.task.classes)
    throw InputError(
        path, 0,
        fmt::format("the model's classes ({}) are not the campaign's ({}): train it "
                    "with the same groups and hold_out",
                    fmt::join(model->classes(), ", "), fmt::join(t.task.classes, ", ")));
  for (const perception::ActionData& action : t.data->actions) try {
      perception::PerformanceReader(*model, action.name, *t.data);
    } catch (const InputError& e) {
      throw InputError(path, 0, e.problem());
    }
  perception::Fold all;
  for (std::size_t s = 0; s < t.data->sessions.size(); ++s)
    all.test_sessions.push_back(static_cast<int>(s));
  t.folds = {all};
  t.fold_of_session.assign(t.data->sessions.size(), 0);
  t.models = {std::move(model)};
}

// The data's sessions by object and name.
std::map<std::pair<int, std::string>, int> session_index(const perception::FeatureSet& data) {
  std::map<std::pair<int, std::string>, int> index;
  for (std::size_t s = 0; s < data.sessions.size(); ++s)
    index[{data.sessions[s].object, data.sessions[s].name}] = static_cast<int>(s);
  return index;
}

// A noisy copy replays in place of the data: the same objects, sessions and rows, in order.
void check_same_rows(const perception::FeatureSet& data, const perception::FeatureSet& copy) {
  bool same = copy.objects == data.objects && copy.sessions.size() == data.sessions.size() &&
              copy.actions.size() == data.actions.size();
  for (std::size_t s = 0; same && s < data.sessions.size(); ++s)
    same = copy.sessions[s].object == data.sessions[s].object &&
           copy.sessions[s].name == data.sessions[s].name;
  for (std::size_t a = 0; same && a < data.actions.size(); ++a) {
    const auto &x = data.actions[a], &y = copy.actions[a];
    same = x.name == y.name && x.rows.size() == y.rows.size();
    for (std::size_t r = 0; same && r < x.rows.size(); ++r)
      same = x.rows[r].object == y.rows[r].object && x.rows[r].session == y.rows[r].session;
  }
  if (!same) throw std::logic_error("a noisy copy of the data does not list the data's rows");
}

// The noisy copy of the world's recordings tree in `copy`, analysed. Null when stopped.
std::shared_ptr<const perception::FeatureSet> analysed_copy(const CampaignConfig& config,
                                                            const robot::WorldNoise& noise,
                                                            const std::filesystem::path& copy,
                                                            loop::Stream stream, bool keep_quiet,
                                                            const ProgressFn& progress,
                                                            const std::atomic<bool>& stop) {
  if (!write_campaign_copy(config, config.world.data, noise, copy, stream, keep_quiet, progress,
                           stop))
    return nullptr;
  return std::make_shared<const perception::FeatureSet>(perception::feature_set_from_recordings(
      perception::load_recording_set(copy.string()), {}, progress, "summary", config.world.series));
}

}  // namespace

DatasetFolds open_dataset(const CampaignConfig& config, const std::vector<ResolvedArm>& arms,
                          InputFiles& files, const ProgressFn& progress) {
  DatasetFolds t;
  if ((config.world.noise.given() || any_trained_in_noise(arms)) &&
      perception::data_kind(config.world.data) != perception::DataKind::recordings)
    throw InputError(config.source, 0,
                     fmt::format("background noise is mixed into recordings, and world.data ({}) "
                                 "is a feature set: give a recordings tree, or no noise",
                                 config.world.data));
  t.data = files.data(config.world.data, progress);
  t.heard = t.data;
  std::optional<perception::ObjectGroups> groups;
  if (!config.world.groups.empty())
    groups = perception::parse_groups(files.text(config.world.groups), config.world.groups);
  t.task = perception::make_dataset_task(*t.data, groups ? &*groups : nullptr,
                                         config.world.hold_out, config.world.groups);
  if (!config.world.model.empty()) {
    open_frozen_model(t, config.world.model, files);
  } else {
    check_enough_for_folds(*t.data, t.task, config.world.data);
    t.folds = perception::make_folds(*t.data, t.task);
    t.fold_of_session.assign(t.data->sessions.size(), -1);
    for (std::size_t f = 0; f < t.folds.size(); ++f)
      for (int s : t.folds[f].test_sessions) t.fold_of_session.at(s) = static_cast<int>(f);
  }
  try {
    t.names = std::make_shared<const pomdp::Problem>(dataset_problem_file(
        loop::dataset_problem_shape(t.task, *t.data, config.task, any_lookalike(arms)),
        config.world.data));
  } catch (const InputError& e) {
    // Only the task can be wrong here (a cost for a behaviour the data does not have).
    throw InputError(config.source, 0, "task." + e.problem());
  }
  return t;
}

std::vector<ObjectGroup> dataset_groups(const DatasetFolds& trials) {
  std::vector<ObjectGroup> groups;
  for (std::size_t o = 0; o < trials.data->objects.size(); ++o) {
    const std::string& name = trials.data->objects[o];
    groups.push_back(
        {name, name, static_cast<int>(sessions_of(*trials.data, static_cast<int>(o)).size())});
  }
  return groups;
}

std::vector<int> right_actions(const DatasetFolds& trials) {
  const int sensing = static_cast<int>(trials.data->actions.size());
  std::vector<int> right;
  for (int bin : trials.task.bin_of_class) right.push_back(sensing + bin);
  const std::size_t states = trials.names->model->object_identification()->data().objects.size();
  right.resize(states, -1);  // the copies of a class: never a trial's truth
  return right;
}

std::vector<std::vector<double>> right_shares(const DatasetFolds& trials,
                                              const loop::TaskSpec& rewards) {
  const pomdp::ObjectProblemData& names = trials.names->model->object_identification()->data();
  const std::size_t sensing = names.sensing.size();
  std::vector<std::vector<double>> shares(names.objects.size(),
                                          std::vector<double>(sensing + names.sorting.size(), 0.0));
  for (std::size_t j = 0; j < names.sorting.size(); ++j)
    for (std::size_t s = 0; s < names.objects.size(); ++s)
      shares[s][sensing + j] =
          (names.sorting_reward[j][s] - rewards.wrong) / (rewards.right - rewards.wrong);
  return shares;
}

bool hear_dataset_in_noise(DatasetFolds& trials, const CampaignConfig& config,
                           const CampaignNoise& noise, const std::filesystem::path& directory,
                           const ProgressFn& progress, const std::atomic<bool>& stop) {
  if (noise.world) {
    auto heard = analysed_copy(config, *noise.world, directory / "heard_recordings",
                               loop::Stream::campaign_heard, false, progress, stop);
    if (!heard) return false;
    check_same_rows(*trials.data, *heard);
    trials.heard = std::move(heard);
  }
  if (noise.training) {
    auto twins =
        analysed_copy(config, *noise.training, directory / "training" / "recordings_in_noise",
                      loop::Stream::campaign_noise, true, progress, stop);
    if (!twins) return false;
    if (twins->objects != trials.data->objects)
      throw std::logic_error("the noisy twins of the data do not list the data's objects");
    trials.twins = std::move(twins);
  }
  return true;
}

namespace {

// Which data a fold model is fitted on: the data or its noisy twins, and the modalities (empty:
// all).
using ModelKey = std::pair<bool, std::vector<std::string>>;

// The fold models the arms hear with: the data's always, the twins' with an arm trained in noise,
// and each set of modalities some arm hears alone.
std::set<ModelKey> model_keys(const DatasetFolds& trials, const std::vector<ResolvedArm>& arms) {
  std::set<ModelKey> keys{{false, {}}};
  if (trials.twins) keys.insert({true, {}});
  for (const ResolvedArm& arm : arms)
    if (!arm.plans_with.modalities.empty())
      keys.insert({arm.plans_with.in_noise, arm.plans_with.modalities});
  return keys;
}

// The data each key's models are fitted on. InputError naming the arm whose modalities the data
// lacks.
std::map<ModelKey, std::shared_ptr<const perception::FeatureSet>> model_data(
    const DatasetFolds& trials, const CampaignConfig& config, const std::vector<ResolvedArm>& arms,
    const std::set<ModelKey>& keys) {
  std::map<ModelKey, std::shared_ptr<const perception::FeatureSet>> data;
  for (const ModelKey& key : keys) {
    const auto& all = key.first ? trials.twins : trials.data;
    if (key.second.empty()) {
      data[key] = all;
      continue;
    }
    try {
      data[key] = std::make_shared<const perception::FeatureSet>(
          perception::keep_modalities(*all, key.second));
    } catch (const InputError& e) {
      const auto arm = std::find_if(arms.begin(), arms.end(), [&](const ResolvedArm& a) {
        return a.plans_with.in_noise == key.first && a.plans_with.modalities == key.second;
      });
      throw InputError(config.source, arm->line,
                       fmt::format("arm '{}': modalities: {}", arm->name, e.problem()));
    }
  }
  return data;
}

}  // namespace

bool fit_dataset_folds(DatasetFolds& trials, const CampaignConfig& config,
                       const std::vector<ResolvedArm>& arms, const ProgressFn& progress,
                       const std::atomic<bool>& stop) {
  if (!config.world.model.empty()) return true;  // frozen: open_dataset loaded it
  perception::FitOptions options = perception::session_fit_options();
  if (!config.training.classifier.empty()) options.classifier = config.training.classifier;
  const std::set<ModelKey> keys = model_keys(trials, arms);
  const auto data = model_data(trials, config, arms, keys);
  trials.models.clear();
  trials.models_in_noise.clear();
  trials.models_of_modalities.clear();
  const auto index = session_index(*trials.data);
  const int folds = static_cast<int>(trials.folds.size());
  for (int f = 0; f < folds; ++f) {
    if (stop.load()) return false;
    if (progress) progress("fit folds", f, folds);
    for (const ModelKey& key : keys) {
      const perception::FeatureSet& set = *data.at(key);
      // A twin's session is its quiet recording's: the fold's held-out sessions stay unheard.
      std::vector<int> training;
      for (std::size_t s = 0; s < set.sessions.size(); ++s) {
        const perception::Session& session = set.sessions[s];
        if (trials.fold_of_session.at(index.at({session.object, session.name})) != f)
          training.push_back(static_cast<int>(s));
      }
      auto model = std::make_shared<const perception::ObservationModel>(
          perception::fit_observation_model(set, trials.task, training, options));
      auto& models = !key.second.empty() ? trials.models_of_modalities[key]
                     : key.first         ? trials.models_in_noise
                                         : trials.models;
      models.push_back(std::move(model));
    }
  }
  if (progress) progress("fit folds", folds, folds);
  return true;
}

namespace {

// The fold's problem for arms of `kind`. When some arm plans with copies of a class, every arm's
// problem has them (those that do not plan with them, with a share of 0).
pomdp::ObjectProblemData fold_problem(const CampaignConfig& config,
                                      const std::vector<ResolvedArm>& arms,
                                      const DatasetFolds& trials, int fold,
                                      const std::vector<int>& uses, const ArmProblemKind& kind) {
  const perception::ObservationModel& model = *trials.model(fold, kind);
  std::optional<double> lookalike_share;
  if (any_lookalike(arms))
    lookalike_share = kind.lookalike ? model.lookalike_share(kind.kind) : 0.0;
  return loop::dataset_problem(trials.task, model, config.task, uses, kind.kind, lookalike_share);
}

// "hear labels", "hear grades and plan with lookalikes", ...
std::string kind_description(const ArmProblemKind& kind) {
  return fmt::format("hear {}{}", perception::observation_kind_name(kind.kind),
                     kind.lookalike ? " and plan with lookalikes" : "");
}

}  // namespace

FoldProblems fold_problems(const CampaignConfig& config, const std::vector<ResolvedArm>& arms,
                           const DatasetFolds& trials) {
  const std::vector<int> uses = loop::default_uses(*trials.data);
  FoldProblems problems;
  for (const ResolvedArm& arm : arms) {
    const ArmProblemKind& kind = arm.plans_with;
    if (problems.count(kind)) continue;
    for (std::size_t f = 0; f < trials.models.size(); ++f)
      problems[kind].push_back(std::make_shared<const pomdp::Problem>(
          dataset_problem_file(fold_problem(config, arms, trials, static_cast<int>(f), uses, kind),
                               fmt::format("{} (fold {})", config.world.data, f + 1))));
  }
  return problems;
}

void write_fold_problems(const std::filesystem::path& directory, const CampaignConfig& config,
                         const FoldProblems& problems) {
  for (const auto& [kind, folds] : problems)
    for (std::size_t f = 0; f < folds.size(); ++f) {
      const std::filesystem::path folder = directory / "folds" / std::to_string(f + 1);
      std::filesystem::create_directories(folder);
      std::ostringstream text;
      text << fmt::format(
          "# Fold {} of the campaign {}\n# (data {}): the problem its arms that {} planned "
          "with, each behaviour limited to the most\n# performances any session recorded (a "
          "trial's own limits may be lower).\n# `echoplan certify --campaign` judges "
          "folds/{}/arms/*/steps.csv with it.\n",
          f + 1, config.source, config.world.data, kind_description(kind), f + 1);
      pomdp::write_problem_yaml(text, folds[f]->model->object_identification()->data(),
                                folds[f]->belief, pomdp::PlannerDefaults{});
      write_file_atomically(folder / fold_problem_name(kind), text.str());
    }
}

bool choose_dataset_unheard(const std::filesystem::path& directory, const CampaignConfig& config,
                            std::vector<ResolvedArm>& arms, const FoldProblems& problems,
                            const ProgressFn& progress, const std::atomic<bool>& stop,
                            int workers) {
  const auto problems_of = [&](std::size_t arm) { return problems.at(arms[arm].plans_with); };
  return choose_arms_unheard(config, arms, problems_of, directory, progress, stop, workers);
}

ArmLoops dataset_loops(const CampaignConfig& config, const std::vector<ResolvedArm>& arms,
                       const DatasetFolds& trials) {
  // One problem per fold and use limits, shared by every arm and trial that needs it.
  using Key = std::tuple<int, std::vector<int>, ArmProblemKind>;
  std::map<Key, std::shared_ptr<const pomdp::Problem>> problems;
  const auto& names = trials.names->model->object_identification()->data();
  const auto problem_for = [&](int fold, const std::vector<int>& uses, const ResolvedArm& arm) {
    auto& p = problems[{fold, uses, arm.plans_with}];
    if (!p)
      p = std::make_shared<const pomdp::Problem>(
          dataset_problem_file(fold_problem(config, arms, trials, fold, uses, arm.plans_with),
                               fmt::format("{} (fold {})", config.world.data, fold + 1)));
    return p;
  };
  ArmLoops loops(arms.size());
  for (std::size_t a = 0; a < arms.size(); ++a)
    for (std::size_t o = 0; o < trials.data->objects.size(); ++o) {
      std::vector<TrialLoop>& group = loops[a].emplace_back();
      for (int session : sessions_of(*trials.data, static_cast<int>(o))) {
        const int fold = trials.fold_of_session.at(session);
        loop::LoopSettings s;
        s.problem = problem_for(fold, loop::session_uses(names, *trials.data, session), arms[a]);
        s.world =
            loop::DatasetWorldSpec{trials.heard, trials.model(fold, arms[a].plans_with), session};
        s.planner = arms[a].planner;
        s.max_steps = config.planner.max_steps;
        group.push_back({std::make_shared<const loop::LoopSpec>(std::move(s)),
                         trials.task.class_of_object.at(o), trials.data->sessions[session].name});
      }
    }
  return loops;
}

}  // namespace echoplan::experiment
