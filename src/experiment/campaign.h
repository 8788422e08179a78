// A campaign from start to report: every check before any work, the training set, the trials, and
// the report rebuilt from what is on disk.
//
// The output folder DIR holds
//   campaign.json        the campaign: its configuration and identity (written before any trial)
//   training/recordings  the synthesised training set (DIR/<object>/<action>/NNN.wav +
//   manifest.csv) journal.jsonl        one line per finished trial (trial_journal.h), in id order
//   once complete trials.csv, steps.csv, arms/<arm>/, summary.json, summary.txt, figures/,
//   index.html
//                        the report: a pure function of the above, rebuilt at the end of every run
// Running the same command again continues the campaign in DIR: finished trials are skipped.
#pragma once

#include <atomic>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "experiment/campaign_config.h"
#include "experiment/campaign_report.h"
#include "experiment/campaign_runner.h"

namespace echoplan::experiment {

// A checked campaign bound to its output folder.
struct Campaign {
  CampaignConfig config;
  std::filesystem::path directory;
  CampaignResults results;                    // spec, particles, planned trials (entries: none yet)
  std::vector<std::string> training_objects;  // the training set's objects and actions
  std::vector<std::string> training_actions;
};

// Checks everything a campaign needs before any work starts, and claims `directory` for it (writes
// campaign.json). Throws InputError, naming the file and the problem, for: a problem that does not
// load or whose objects, actions or observations differ from the other arms' or the world's; an
// object the problems do not know; an object with no catalogue entry; a missing recordings folder;
// an unknown solver; an output folder that cannot be written or that holds a different campaign.
Campaign open_campaign(const CampaignConfig& config, const std::filesystem::path& directory);

// Where the training recordings are: training_set.recordings, else DIR/training/recordings.
std::filesystem::path training_recordings(const Campaign& campaign);

// Synthesises the training set into DIR/training/recordings unless it is complete already or the
// campaign uses existing recordings. `progress(done, total)` after each clip. Returns false when
// stopped.
bool synthesise_training_set(const Campaign& campaign,
                             const std::function<void(int, int)>& progress,
                             const std::atomic<bool>& stop);

// The world of the campaign's trials, for run_campaign_trials.
WorldFactory make_world(const Campaign& campaign);

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
