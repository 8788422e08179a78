// A campaign from start to report: every check before any work, the training set, the trials, and
// the report rebuilt from what is on disk.
//
// The output folder DIR holds:
// - campaign.json: the campaign: its configuration as the file gives it, what each arm runs (its
//   resolved arm, campaign_arms.h; rewritten once self-play has chosen) and the identity (written
//   before any trial);
// - training/: the synthesised training set (recordings/<object>/<action>/NNN.wav, manifest.csv),
//   the classifier trained on it (model.json) and each calibrating arm's problem;
// - journal.jsonl: one line per finished trial (trial_journal.h), in id order once complete;
// - report_inputs.json (and unheard.json when an arm chose): what prepare_training worked out for
//   the report besides the trials (report_inputs.h);
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
#include "experiment/campaign_world.h"

namespace echoplan::experiment {

// A checked campaign bound to its output folder: the specification (configuration, folder, the
// report's skeleton) and its world, with every input loaded once and shared read-only by the
// workers. The journal on disk is the only state that changes as trials finish.
struct Campaign {
  CampaignConfig config;  // the file as written (the world's trial groups: results.groups)
  std::filesystem::path directory;
  // spec, particles, planned trials, presentation (entries: none yet) and what each arm runs
  // (results.arms: resolve_arms, with what self-play chose once prepare_training() has run)
  CampaignResults results;
  std::shared_ptr<const CampaignWorld> world;  // as open() left it: prepare() only reads it
  // Filled by prepare_training(): the checked loop of each arm and group, what the workers run.
  ArmLoops loops;
};

// Checks everything a campaign needs before any work starts, and claims `directory` for it (writes
// campaign.json). Throws InputError, naming the file and the problem, for: a problem that does not
// load or whose objects, actions or observations differ from the other arms' or the world's; an
// object the problems do not know; an object with no catalogue entry; a missing recordings folder;
// a given model trained for other objects or actions; data too small for its folds, or a frozen
// model of other classes; an unknown solver; an output folder that cannot be written or that holds
// a different campaign.
Campaign open_campaign(const CampaignConfig& config, const std::filesystem::path& directory);

// Prepares what the trials need (CampaignWorld::prepare: each fold's model, synthesised, trained
// or fitted, each `unheard: auto` arm's estimate chosen, and the loops) on `workers` threads.
// `progress(stage, done, total)` reports its stages. Returns false when stopped.
bool prepare_training(Campaign& campaign, const ProgressFn& progress, const std::atomic<bool>& stop,
                      int workers = 1);

// The trials of `shard` that DIR's journal does not hold yet, in id order.
std::vector<TrialJob> remaining_jobs(const Campaign& campaign, const Shard& shard);

// Rebuilds the report from DIR's journal (sorting the journal by id first) and the files
// prepare_training left, and returns the summary text: it synthesises, opens and fits nothing. With
// `figures` false, no figures or page (for quick checks).
std::string rebuild_report(const Campaign& campaign, bool figures = true);

// Joins the shard folders of one campaign into `directory`: the same campaign.json in each (else
// InputError), the training set of the first, every journal entry (an id present twice must be the
// same trial), then the report. The result is byte for byte the folder one unsharded run writes.
std::string merge_campaigns(const std::filesystem::path& directory,
                            const std::vector<std::filesystem::path>& shards);

}  // namespace echoplan::experiment
