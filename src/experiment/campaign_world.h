// The world of a campaign: where its trials act, one class per kind of world. A campaign is folds x
// arms x trials in every world: recorded data has a fold per held-out share of its sessions (or
// one, with a frozen model); a model or simulated world is one fold whose training data is
// synthesised or given. make_campaign_world() is the one place the kinds are told apart; the
// campaign and its report ask the world instead.
//   model      a problem file's own table draws each observation (a planner study, no sound);
//   simulated  the simulated robot acts, the simulated recorder records, the trained classifier
//              hears;
//   dataset    recorded data replayed, heard by each fold's fitted model or a frozen model.
#pragma once

#include <atomic>
#include <filesystem>
#include <memory>
#include <optional>
#include <vector>

#include "common/progress.h"
#include "experiment/campaign_arms.h"
#include "experiment/campaign_config.h"
#include "experiment/campaign_report.h"
#include "experiment/campaign_runner.h"
#include "experiment/input_files.h"

namespace echoplan::experiment {

class CampaignWorld {
 public:
  virtual ~CampaignWorld() = default;
  // Loads and checks everything the world needs before any work (files read once through
  // `files`), each arm against the problem it plans on (check_arm_problem): InputError naming the
  // file and the problem. Fills the world's facts and the report's skeleton in `results`: the trial
  // groups (the file's, or for recorded data one per object, a trial per session), spec and
  // presentation. The configuration stays as the file wrote it.
  virtual void open(const CampaignConfig& config, const std::vector<ResolvedArm>& arms,
                    CampaignResults& results, InputFiles& files) = 0;
  // Trains or fits each fold's model (progress: "synthesise", the trainer's stages, "fit folds",
  // "choose unheard"), puts what self-play chose in the arms' planners, writes what the report
  // shows of the world besides the trials (report_inputs.h), and returns the checked loop of every
  // arm, group and trial; nothing when stopped. `workers` threads share what can run in parallel
  // (results do not depend on it). What it fits or trains goes into the loops and the folder: the
  // world stays as open() left it, so preparing again starts from the same place.
  virtual std::optional<ArmLoops> prepare(const CampaignConfig& config,
                                          std::vector<ResolvedArm>& arms,
                                          const ProgressFn& progress, const std::atomic<bool>& stop,
                                          int workers) const = 0;
};

// The world of `config`; what it writes (a synthesised training set, the trained model, the
// calibrated problems) goes under `directory`/training.
std::unique_ptr<CampaignWorld> make_campaign_world(const CampaignConfig& config,
                                                   const std::filesystem::path& directory);

}  // namespace echoplan::experiment
