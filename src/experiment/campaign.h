// A campaign from start to report: every check before any work, the training set, the trials, and
// the report rebuilt from what is on disk.
//
// The output folder DIR holds:
// - campaign.json: the campaign, its configuration and identity (written before any trial);
// - training/: the synthesised training set (recordings/<object>/<action>/NNN.wav, manifest.csv),
//   the classifier trained on it (model.json) and each calibrating arm's problem;
// - journal.jsonl: one line per finished trial (trial_journal.h), in id order once complete;
// - the report, a pure function of the above rebuilt at the end of every run: trials.csv,
//   steps.csv, arms/<arm>/, summary.json, summary.txt, figures/, index.html.
// Running the same command again continues the campaign in DIR: finished trials are skipped.
#pragma once

#include <atomic>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "experiment/campaign_config.h"
#include "experiment/campaign_report.h"
#include "experiment/campaign_runner.h"
#include "experiment/dataset_campaign.h"
#include "perception/observation_model.h"
#include "pomdp/problem.h"
#include "sim/catalogue.h"
#include "sim/sim_config.h"

namespace echoplan::experiment {

// A checked campaign bound to its output folder, with every input loaded once and shared
// read-only by the workers.
struct Campaign {
  CampaignConfig config;
  std::filesystem::path directory;
  CampaignResults results;                    // spec, particles, planned trials (entries: none yet)
  std::vector<std::string> training_objects;  // the training set's objects and actions
  std::vector<std::string> training_actions;
  std::shared_ptr<const pomdp::Problem> world_problem;
  // Each arm's problem as its file says; prepare_training() puts a calibrating arm's calibrated
  // problem in its place.
  std::vector<std::shared_ptr<const pomdp::Problem>> arm_problems;
  std::shared_ptr<const sim::Catalogue> catalogue;
  std::shared_ptr<const sim::SimConfig> sim_config;
  // Filled by open_campaign() (training_set.model) or prepare_training() (trained, when needed).
  std::shared_ptr<const perception::ObservationModel> observation_model;
  // A dataset world's data, folds and (after prepare_training()) fitted fold models.
  std::shared_ptr<DatasetTrials> dataset;
  // Filled by prepare_training(): the checked loop of each arm and group, what the workers run.
  ArmLoops loops;
};

// True when the campaign needs a trained classifier: an arm calibrates or the world is simulated.
bool needs_classifier(const CampaignConfig& config);

// Checks everything a campaign needs before any work starts, and claims `directory` for it (writes
// campaign.json). Throws InputError, naming the file and the problem, for: a problem that does not
// load or whose objects, actions or observations differ from the other arms' or the world's; an
// object the problems do not know; an object with no catalogue entry; a missing recordings folder;
// a given model trained for other objects or actions; an unknown solver; an output folder that
// cannot be written or that holds a different campaign.
Campaign open_campaign(const CampaignConfig& config, const std::filesystem::path& directory);

// Where the training recordings are: training_set.recordings, else DIR/training/recordings.
std::filesystem::path training_recordings(const Campaign& campaign);

// Prepares what the trials need. A dataset world: fits each fold's classifiers and table
// ("fit folds" progress). Otherwise: synthesises the training set into DIR/training/recordings
// (unless it is complete already or the campaign uses existing recordings), then, when
// needs_classifier(), trains and calibrates the classifier on it (or loads training_set.model, or
// DIR/training/model.json of an earlier run), calibrates each calibrating arm's problem in memory
// (writing it to DIR/training/<arm>.problem.yaml for the user) and checks every arm's loop.
// `progress(stage, done, total)` reports "synthesise" clips and the trainer's stages. Returns false
// when stopped.
bool prepare_training(Campaign& campaign, const ProgressFn& progress,
                      const std::atomic<bool>& stop);

// The trials of `shard` that DIR's journal does not hold yet, in id order.
std::vector<TrialJob> remaining_jobs(const Campaign& campaign, const Shard& shard);

// Rebuilds the report from DIR's journal (sorting the journal by id first) and returns the summary
// text. With `figures` false, no figures or page (for quick checks).
std::string rebuild_report(const Campaign& campaign, bool figures = true);

// Joins the shard folders of one campaign into `directory`: the same campaign.json in each (else
// InputError), the training set of the first, every journal entry (an id present twice must be the
// same trial), then the report. The result is byte for byte the folder one unsharded run writes.
std::string merge_campaigns(const std::filesystem::path& directory,
                            const std::vector<std::filesystem::path>& shards);

}  // namespace echoplan::experiment
