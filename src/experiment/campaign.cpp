#include "experiment/campaign.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "common/error.h"
#include "common/file_io.h"
#include "experiment/campaign_figures.h"
#include "experiment/html_report.h"
#include "experiment/report_inputs.h"
#include "experiment/unheard_choice.h"

namespace echoplan::experiment {

namespace {

namespace fs = std::filesystem;

constexpr const char* kJournal = "journal.jsonl";
constexpr const char* kDescription = "campaign.json";

// The output folder exists and takes files.
void check_writable(const fs::path& directory) {
  std::error_code error;
  fs::create_directories(directory, error);
  if (error)
    throw InputError(directory.string(), 0, "cannot create the output folder: " + error.message());
  const fs::path probe = directory / ".echoplan-write-test";
  {
    std::ofstream out(probe);
    out << "probe\n";
    if (!out) throw InputError(directory.string(), 0, "the output folder cannot be written");
  }
  fs::remove(probe, error);
}

// campaign.json: the configuration, what each arm runs, the identity.
void write_description(const Campaign& c) {
  nlohmann::json arms = nlohmann::json::array();
  for (const ResolvedArm& arm : c.results.arms)
    arms.push_back(to_json(arm, c.config.world.recorded_data()));
  const nlohmann::json j = {
      {"config", to_json(c.config)}, {"arms", std::move(arms)}, {"identity", c.results.identity}};
  write_file_atomically(c.directory / kDescription, j.dump(2) + "\n");
}

// Puts the choices an earlier preparation of this campaign made (unheard.json) in its arms.
void apply_folder_choices(Campaign& c) {
  if (!fs::exists(c.directory / kUnheardChoices)) return;
  apply_unheard_choices(read_unheard_choices(c.directory / kUnheardChoices), c.results.arms);
}

// The folder holds this campaign or none: claims it by writing campaign.json (with the choices
// of an earlier run in it, if any), and keeps there a recordings tree's audio analysed on opening.
void claim_folder(Campaign& c, InputFiles& files) {
  check_writable(c.directory);
  const fs::path described = c.directory / kDescription;
  c.results.identity = c.config.identity(files, c.results.groups);
  if (fs::exists(described)) {
    const nlohmann::json theirs = nlohmann::json::parse(
        read_text_file(described.string(), "campaign description"), nullptr, false);
    if (theirs.is_discarded() || !theirs.contains("identity") ||
        theirs["identity"] != c.results.identity)
      throw InputError(
          c.directory.string(), 0,
          "holds a different campaign (its campaign.json differs from this configuration); "
          "choose another --out, or remove the folder to start again");
    apply_folder_choices(c);
  }
  write_description(c);
  files.keep_analysed();
}

// open_campaign, reading a recordings tree's analysed audio back from the first of `kept_in` that
// kept it (the campaign's folder; a merge's shards too) instead of analysing it again.
Campaign open_in(const CampaignConfig& config, const fs::path& directory,
                 std::vector<fs::path> kept_in) {
  Campaign c;
  c.config = config;
  c.results.arms = resolve_arms(config);
  c.directory = directory;
  std::unique_ptr<CampaignWorld> world = make_campaign_world(config, directory);
  InputFiles files(std::move(kept_in), config.world.series);
  world->open(c.config, c.results.arms, c.results, files);
  c.world = std::move(world);  // from now on what it opened is only read
  c.results.config = c.config;
  c.results.planned_trials = static_cast<int>(
      campaign_jobs(static_cast<int>(c.config.arms.size()), c.results.groups).size());
  claim_folder(c, files);
  return c;
}

}  // namespace

Campaign open_campaign(const CampaignConfig& config, const fs::path& directory) {
  return open_in(config, directory, {directory});
}

bool prepare_training(Campaign& campaign, const ProgressFn& progress, const std::atomic<bool>& stop,
                      int workers) {
  // A stopped preparation leaves the arms as they were.
  std::vector<ResolvedArm> arms = campaign.results.arms;
  std::optional<ArmLoops> loops =
      campaign.world->prepare(campaign.config, arms, progress, stop, workers);
  if (!loops) return false;
  campaign.results.arms = std::move(arms);
  campaign.loops = std::move(*loops);
  write_description(campaign);
  return true;
}

std::vector<TrialJob> remaining_jobs(const Campaign& campaign, const Shard& shard) {
  std::set<int> done;
  for (const JournalEntry& e : read_journal(campaign.directory / kJournal)) done.insert(e.id);
  std::vector<TrialJob> jobs;
  for (const TrialJob& job :
       campaign_jobs(static_cast<int>(campaign.config.arms.size()), campaign.results.groups))
    if (shard.contains(job.id) && !done.count(job.id)) jobs.push_back(job);
  return jobs;
}

std::string rebuild_report(const Campaign& campaign, bool figures) {
  const fs::path& dir = campaign.directory;
  std::vector<JournalEntry> entries = read_journal(dir / kJournal);
  // One entry per id (a trial journalled twice by overlapping runs is the same trial), in id order.
  std::map<int, JournalEntry> by_id;
  for (JournalEntry& e : entries) by_id.emplace(e.id, std::move(e));
  entries.clear();
  for (auto& [id, e] : by_id) entries.push_back(std::move(e));
  write_journal(dir / kJournal, entries);

  CampaignResults results = campaign.results;
  results.entries = std::move(entries);
  ReportInputs inputs = read_report_inputs(dir);
  results.heard = std::move(inputs.heard);
  if (fs::exists(dir / kUnheardChoices))
    results.unheard_choices = read_unheard_choices(dir / kUnheardChoices);
  write_tables(dir, results);
  write_file_atomically(dir / "summary.json", summary_json(results).dump(2) + "\n");
  const std::string text = summary_text(results);
  write_file_atomically(dir / "summary.txt", text);
  if (figures) {
    const std::vector<Figure> drawn = draw_figures(dir, results, inputs.templates);
    write_file_atomically(dir / "index.html", html_report(dir, results, drawn));
  }
  return text;
}

std::string merge_campaigns(const fs::path& directory, const std::vector<fs::path>& shards) {
  if (shards.empty()) throw InputError("merge: name at least one shard folder");
  nlohmann::json first;
  for (const fs::path& shard : shards) {
    const fs::path described = shard / kDescription;
    if (!fs::exists(described))
      throw InputError(shard.string(), 0, "is not a campaign folder (no campaign.json)");
    const nlohmann::json j = nlohmann::json::parse(
        read_text_file(described.string(), "campaign description"), nullptr, false);
    if (j.is_discarded() || !j.contains("identity") || !j.contains("config"))
      throw InputError(described.string(), 0, "is not a campaign description");
    if (first.is_null())
      first = j;
    else if (j["identity"] != first["identity"])
      throw InputError(shard.string(), 0,
                       fmt::format("holds another campaign than {} (their campaign.json differ)",
                                   shards[0].string()));
  }
  for (const fs::path& shard : shards)
    if (fs::exists(directory) && fs::equivalent(shard, directory))
      throw InputError(directory.string(), 0, "the merged folder must not be one of the shards");
  const CampaignConfig config =
      campaign_config_from_json(first["config"], (shards[0] / kDescription).string());
  std::vector<fs::path> kept_in{directory};
  kept_in.insert(kept_in.end(), shards.begin(), shards.end());
  Campaign campaign = open_in(config, directory, std::move(kept_in));

  // The training set of the first shard that has one (every shard synthesised the same one).
  if (config.training.recordings.empty())
    for (const fs::path& shard : shards) {
      const fs::path source = shard / "training";
      if (!fs::is_directory(source)) continue;
      std::error_code error;
      fs::remove_all(directory / "training", error);
      fs::copy(source, directory / "training", fs::copy_options::recursive, error);
      if (error)
        throw InputError((directory / "training").string(), 0,
                         "cannot copy the training set: " + error.message());
      break;
    }

  // What prepare left for the report likewise (every shard made the same).
  for (const char* prepared : {kUnheardChoices, kReportInputs})
    for (const fs::path& shard : shards)
      if (fs::exists(shard / prepared)) {
        write_file_atomically(directory / prepared,
                              read_text_file((shard / prepared).string(), prepared));
        break;
      }

  // The arms as the shards ran them.
  apply_folder_choices(campaign);
  write_description(campaign);

  std::map<int, JournalEntry> by_id;
  for (const fs::path& shard : shards)
    for (JournalEntry& e : read_journal(shard / kJournal)) {
      auto [it, inserted] = by_id.emplace(e.id, e);
      if (!inserted && !(it->second == e))
        throw InputError(
            (shard / kJournal).string(), 0,
            fmt::format("trial {} differs from the same trial in another shard", e.id));
    }
  for (JournalEntry& e : read_journal(directory / kJournal)) by_id.emplace(e.id, std::move(e));
  std::vector<JournalEntry> entries;
  for (auto& [id, e] : by_id) entries.push_back(std::move(e));
  write_journal(directory / kJournal, entries);
  return rebuild_report(campaign);
}

}  // namespace echoplan::experiment
