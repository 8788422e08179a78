// Campaigns from Python: a campaign file run into an output folder, step for step what `echoplan
// experiment` does (apps/echoplan/commands/experiment.cpp), without its progress bars. The results
// are read back from the folder's files by echoplan/campaigns.py, so Python sees exactly what the
// command leaves on disk and nothing of the campaign's internals.
#include <pybind11/stl.h>

#include <algorithm>
#include <optional>
#include <thread>

#include "bindings.h"
#include "experiment/campaign.h"
#include "experiment/trial_journal.h"
#include "interrupt.h"

namespace echoplan::python {

namespace {

// Runs (or continues) the campaign and returns the report's summary text. Ctrl-C stops the
// workers after their step in progress; the report is rebuilt from the finished trials before
// the KeyboardInterrupt, and the same call continues the campaign.
std::string run_campaign(const std::string& config_path, const std::string& out,
                         std::optional<int> workers, std::optional<std::uint64_t> seed,
                         const std::string& shard_text, bool figures) {
  experiment::CampaignConfig config = experiment::load_campaign_config(config_path);
  if (seed) config.seed = *seed;
  const experiment::Shard shard = experiment::parse_shard(shard_text);
  experiment::Campaign campaign = experiment::open_campaign(config, out);
  experiment::CampaignRunOptions options;
  options.workers = workers.value_or(std::max(1u, std::thread::hardware_concurrency()));
  if (options.workers < 1) throw py::value_error("workers must be >= 1");
  return run_interruptibly([&](const std::atomic<bool>& stop) {
    if (!experiment::prepare_training(campaign, {}, stop, options.workers)) return std::string();
    const auto jobs = experiment::remaining_jobs(campaign, shard);
    experiment::TrialJournal journal(campaign.directory / "journal.jsonl");
    options.stop = &stop;
    if (!jobs.empty())
      experiment::run_campaign_trials(campaign.config, campaign.results.groups, campaign.loops,
                                      jobs, journal, options);
    return experiment::rebuild_report(campaign, figures);
  });
}

}  // namespace

void bind_campaigns(py::module_& m) {
  m.def("_run_campaign", &run_campaign, py::arg("config"), py::arg("out"), py::kw_only(),
        py::arg("workers") = py::none(), py::arg("seed") = py::none(), py::arg("shard") = "1/1",
        py::arg("figures") = true,
        "Runs a campaign file into `out` as `echoplan experiment --config CONFIG --out OUT` does "
        "and returns the summary text. echoplan.run_campaign wraps it and reads the results.");
  m.def("default_campaign_path", &experiment::default_campaign_path,
        "The shipped campaign of the main job (experiments/chapter5.yaml).");
}

}  // namespace echoplan::python
