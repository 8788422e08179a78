// A campaign in a dataset world: recorded data replayed, a trial per (object, session), for every
// arm, paired.
//
// The data is a feature set or a recordings tree (docs/feature-sets.md); the groups file, when
// given, says what the objects are sorted by. The sessions are dealt into folds (one session of
// every object per fold when a trial holds out a session; whole objects when it holds out the
// object) and each fold's classifiers and calibrated table are fitted once, on the other folds
// only, then shared by every arm and trial of the fold. A trial's problem is its fold's, with each
// sensing action limited to the performances its session recorded.
#pragma once

#include <atomic>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <vector>

#include "common/progress.h"
#include "experiment/campaign_arms.h"
#include "experiment/campaign_config.h"
#include "experiment/campaign_noise.h"
#include "experiment/campaign_runner.h"
#include "experiment/input_files.h"
#include "perception/dataset_folds.h"
#include "perception/dataset_task.h"
#include "perception/feature_set.h"
#include "perception/fit_observation_model.h"
#include "pomdp/problem.h"

namespace echoplan::experiment {

// A dataset world's data dealt into folds, with each fold's fitted model: what its trials replay.
struct DatasetFolds {
  std::shared_ptr<const perception::FeatureSet> data;
  perception::DatasetTask task;
  std::vector<perception::Fold> folds;
  std::vector<int> fold_of_session;  // [session] -> fold
  // The fitted model of each fold (empty until fit_dataset_folds()).
  std::vector<std::shared_ptr<const perception::ObservationModel>> models;
  // What the trials hear: `data`, or with world.noise its noisy copy (the same sessions and rows,
  // once hear_dataset_in_noise() made it).
  std::shared_ptr<const perception::FeatureSet> heard;
  // With an arm trained in noise: the data with a noisy twin of each performance in its session
  // (hear_dataset_in_noise()), and each fold's model fitted on the twins of its training sessions.
  std::shared_ptr<const perception::FeatureSet> twins;
  std::vector<std::shared_ptr<const perception::ObservationModel>> models_in_noise;
  // With an arm that hears some modalities only: each fold's model fitted on them, by (trained in
  // noise, the modalities).
  std::map<std::pair<bool, std::vector<std::string>>,
           std::vector<std::shared_ptr<const perception::ObservationModel>>>
      models_of_modalities;

  // The model that an arm of `kind` hears fold `fold` with.
  const std::shared_ptr<const perception::ObservationModel>& model(
      int fold, const ArmProblemKind& kind) const {
    if (!kind.modalities.empty())
      return models_of_modalities.at({kind.in_noise, kind.modalities}).at(fold);
    return kind.in_noise ? models_in_noise.at(fold) : models.at(fold);
  }
  // Names only (objects, actions, symbols): what the report needs before any fit.
  std::shared_ptr<const pomdp::Problem> names;
};

// Loads (through `files`, each input read once) and checks the world's data, groups and frozen
// model (InputError naming the file and line; a feature set with noise to hear) and deals the
// folds; the names problem has the copies of a class some arm plans with. A recordings tree's
// audio is analysed now (`progress` hears "analyse").
DatasetFolds open_dataset(const CampaignConfig& config, const std::vector<ResolvedArm>& arms,
                          InputFiles& files, const ProgressFn& progress = {});

// The trial groups of the data: one per object, in the data's order, a trial per session.
std::vector<ObjectGroup> dataset_groups(const DatasetFolds& trials);

// The action that sorts each class right, for the report's accuracy (CampaignResults); the
// lookalike copies of the classes have -1: a trial's truth is always a class.
std::vector<int> right_actions(const DatasetFolds& trials);
// Per state of the names problem (classes, then their copies) and action, the chance that the
// action sorts an object in that state right: (reward - wrong) / (right - wrong) for a sorting
// action (1 or 0 for a class, the share of the other classes in the bin for
// a lookalike), 0 for a sensing action. What the belief at a sort is measured with.
std::vector<std::vector<double>> right_shares(const DatasetFolds& trials,
                                              const loop::TaskSpec& rewards);

// With world.noise or an arm trained in noise: writes the noisy copies of the world's recordings
// tree into `directory` (the trials' in heard_recordings/, the training twins in
// training/recordings_in_noise/) and analyses them into `trials.heard` and `trials.twins`.
// (open_dataset refused a feature set: noise is mixed into recordings). False when stopped.
bool hear_dataset_in_noise(DatasetFolds& trials, const CampaignConfig& config,
                           const CampaignNoise& noise, const std::filesystem::path& directory,
                           const ProgressFn& progress, const std::atomic<bool>& stop);

// Fits every fold's model, with the twins its model trained in noise, and for the arms that hear
// some modalities only its model on those (`progress` hears "fit folds"). InputError naming the
// arm for a modality the data lacks. Returns false when stopped.
bool fit_dataset_folds(DatasetFolds& trials, const CampaignConfig& config,
                       const std::vector<ResolvedArm>& arms, const ProgressFn& progress,
                       const std::atomic<bool>& stop);

// Each kind of arm's problem of each fold, [kind][fold]: the fold's fitted table, the task's
// rewards and costs, each behaviour limited to the most performances any session recorded
// (default_uses), an exact belief (as the campaign's trials track it). Needs the fitted folds.
using FoldProblems = std::map<ArmProblemKind, std::vector<std::shared_ptr<const pomdp::Problem>>>;
FoldProblems fold_problems(const CampaignConfig& config, const std::vector<ResolvedArm>& arms,
                           const DatasetFolds& trials);

// Writes each fold's problems, `directory`/folds/<fold>/<fold_problem_name> (folds numbered from
// 1). `echoplan certify --campaign` judges the fold's trials with them.
void write_fold_problems(const std::filesystem::path& directory, const CampaignConfig& config,
                         const FoldProblems& problems);

// choose_arms_unheard (experiment/unheard_choice.h), each arm playing its kind's fold problems
// (arms of one kind share them, and so one choice). False when stopped.
bool choose_dataset_unheard(const std::filesystem::path& directory, const CampaignConfig& config,
                            std::vector<ResolvedArm>& arms, const FoldProblems& problems,
                            const ProgressFn& progress, const std::atomic<bool>& stop, int workers);

// The loop of every arm and trial: loops[arm][object][session] (campaign_runner.h). Needs the
// fitted folds.
ArmLoops dataset_loops(const CampaignConfig& config, const std::vector<ResolvedArm>& arms,
                       const DatasetFolds& trials);

}  // namespace echoplan::experiment
