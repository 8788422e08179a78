// `echoplan experiment`: the project's main job, the report's chapter 5 as one command (a campaign:
// training set, trials of every arm, report with figures and index.html).
#include <fmt/core.h>
#include <spdlog/spdlog.h>

#include <atomic>
#include <chrono>
#include <memory>
#include <thread>

#include "commands/commands.h"
#include "common/error.h"
#include "common/stop_signal.h"
#include "experiment/campaign.h"
#include "experiment/progress_bar.h"

namespace echoplan::cli {

namespace {

struct ExperimentFlags {
  std::string config;
  std::string out;
  std::string shard = "1/1";
  int workers = 0;
  std::uint64_t seed = 0;
  bool seed_given = false;
};

void run_experiment(const ExperimentFlags& f) {
  const std::string config_path = f.config.empty() ? experiment::default_campaign_path() : f.config;
  experiment::CampaignConfig config = experiment::load_campaign_config(config_path);
  if (f.seed_given) config.seed = f.seed;
  const experiment::Shard shard = experiment::parse_shard(f.shard);
  const int workers = f.workers > 0 ? f.workers : std::max(1u, std::thread::hardware_concurrency());
  // Every check before any work.
  experiment::Campaign campaign = experiment::open_campaign(config, f.out);

  // Ctrl-C (or SIGTERM) stops the workers after their step in progress; finished trials are in the
  // journal already, and the report is rebuilt from them before exiting.
  const StopSignal stop;
  const std::atomic<bool>& stop_requested = stop.flag();

  const auto start = std::chrono::steady_clock::now();
  spdlog::info("campaign {} -> {} ({} trials{}, {} workers)", config_path, f.out,
               campaign.results.planned_trials,
               shard.count > 1 ? fmt::format(", shard {}/{}", shard.index, shard.count) : "",
               workers);
  {
    // One bar per stage of the preparation (synthesis, then the trainer's stages).
    std::unique_ptr<experiment::ProgressBar> bar;
    std::string stage;
    const bool complete = experiment::prepare_training(
        campaign,
        [&](const std::string& what, int done, int total) {
          if (what != stage) {
            if (bar) bar->finish();
            stage = what;
            bar = std::make_unique<experiment::ProgressBar>(
                what == "synthesise" ? "training clips" : what, total);
          }
          bar->update(done);
        },
        stop_requested, workers);
    if (bar) bar->finish();
    if (!complete) {
      spdlog::warn(
          "interrupted while preparing the training set; run the same command again to continue");
      throw Interrupted{};
    }
  }
  const double preparation_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  const std::vector<experiment::TrialJob> jobs = experiment::remaining_jobs(campaign, shard);
  int shard_total = 0;
  for (const experiment::TrialJob& job : experiment::campaign_jobs(
           static_cast<int>(campaign.config.arms.size()), campaign.results.groups))
    shard_total += shard.contains(job.id);
  const int already = shard_total - static_cast<int>(jobs.size());
  if (already > 0)
    spdlog::info("{} of {} trials already in {}; running the other {}", already, shard_total, f.out,
                 jobs.size());
  experiment::ProgressBar bar("trials", shard_total, already);
  int done = already;
  experiment::TrialJournal journal(campaign.directory / "journal.jsonl");
  experiment::CampaignRunOptions options;
  options.workers = workers;
  options.stop = &stop_requested;
  options.on_trial = [&](const experiment::JournalEntry&) { bar.update(++done); };
  const auto trials_start = std::chrono::steady_clock::now();
  if (!jobs.empty()) {
    bar.update(done);
    experiment::run_campaign_trials(campaign.config, campaign.results.groups, campaign.loops, jobs,
                                    journal, options);
    bar.finish();
  }
  const double trial_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - trials_start).count();

  const auto report_start = std::chrono::steady_clock::now();
  const std::string summary = experiment::rebuild_report(campaign);
  const double report_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - report_start).count();
  fmt::print("{}\n", summary);
  fmt::print(
      "time: preparation (training set and classifier, or folds) {:.1f} s, trials {:.1f} s, report "
      "{:.1f} s\n",
      preparation_seconds, trial_seconds, report_seconds);
  fmt::print("report: {}/index.html\n", f.out);
  if (stop_requested) {
    spdlog::warn("interrupted: {} of {} trials are in {}; the same command continues the campaign",
                 done, shard_total, f.out);
    throw Interrupted{};
  }
}

}  // namespace

void add_experiment_command(CLI::App& app) {
  auto flags = std::make_shared<ExperimentFlags>();
  auto* cmd = app.add_subcommand("experiment",
                                 "The main job: the report's chapter 5 as one campaign. "
                                 "Synthesises the training set, runs the\n"
                                 "trials of every arm (10 per object, then the weighted can and "
                                 "mug), and writes DIR/trials.csv,\n"
                                 "steps.csv, summary.json, figures/ and index.html. Runs again in "
                                 "the same DIR continue where the\n"
                                 "last stopped. Example:\n"
                                 "  echoplan experiment --out results/chapter5\n"
                                 "  echoplan experiment --config experiments/chapter5.yaml --shard "
                                 "2/4 --out shards/2   (then merge)");
  cmd->add_option(
      "--config", flags->config,
      "Campaign file (YAML; default: experiments/chapter5.yaml, the report's chapter 5)");
  cmd->add_option("--out", flags->out,
                  "Output folder (created; an existing one of the same campaign is continued)")
      ->required();
  cmd->add_option("--workers", flags->workers,
                  "Trials run in parallel (default: all cores); results do not change")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--shard", flags->shard,
                  "Run share I of N (1 <= I <= N) of the trials, for a cluster's array job; join "
                  "with `echoplan merge`")
      ->capture_default_str();
  cmd->add_option_function<std::uint64_t>(
      "--seed", [flags](std::uint64_t seed) { flags->seed = seed, flags->seed_given = true; },
      "Seed of every random choice (default: the campaign file's)");
  cmd->callback([flags] { run_experiment(*flags); });
}

}  // namespace echoplan::cli
