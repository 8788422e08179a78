#include "experiment/campaign_runner.h"

#include <charconv>
#include <map>
#include <memory>
#include <mutex>

#include "common/error.h"
#include "common/parallel_jobs.h"
#include "common/rng.h"
#include "common/stable_hash.h"
#include "pomdp/problem.h"

namespace echoplan::experiment {

namespace {

// What one worker owns: a loop per shared spec it has met (a per-trial spec's loop lives for its
// trial only).
class Worker {
 public:
  explicit Worker(const ArmLoops& loops) : loops_(loops) {}

  std::optional<loop::Trial> run(const TrialJob& job, std::uint64_t seed,
                                 const std::atomic<bool>* stop) {
    const TrialLoop& trial = trial_loop(loops_, job);
    const loop::TrialRequest request{job.index, trial.true_state, seed};
    if (loops_[job.arm][job.group].size() != 1)
      return loop::Loop(trial.spec).run(request, {}, stop);
    auto it = mine_.find(trial.spec.get());
    if (it == mine_.end()) it = mine_.emplace(trial.spec.get(), loop::Loop(trial.spec)).first;
    return it->second.run(request, {}, stop);
  }

 private:
  const ArmLoops& loops_;
  std::map<const loop::LoopSpec*, loop::Loop> mine_;
};

}  // namespace

std::vector<TrialJob> campaign_jobs(int arms, const std::vector<ObjectGroup>& groups) {
  std::vector<TrialJob> jobs;
  int id = 0;
  for (int a = 0; a < arms; ++a)
    for (int g = 0; g < static_cast<int>(groups.size()); ++g)
      for (int i = 0; i < groups[static_cast<std::size_t>(g)].trials; ++i)
        jobs.push_back({id++, a, g, i});
  return jobs;
}

const TrialLoop& trial_loop(const ArmLoops& loops, const TrialJob& job) {
  const std::vector<TrialLoop>& group = loops.at(job.arm).at(job.group);
  return group.size() == 1 ? group[0] : group.at(job.index);
}

std::uint64_t group_seed(std::uint64_t seed, const ObjectGroup& group) {
  return derive_seed(seed, {stable_hash(group.object)});
}

Shard parse_shard(const std::string& text) {
  const std::size_t slash = text.find('/');
  Shard shard;
  auto parse = [&](std::string_view part, int& value) {
    const auto [end, error] = std::from_chars(part.data(), part.data() + part.size(), value);
    return error == std::errc() && end == part.data() + part.size();
  };
  const std::string_view all(text);
  if (slash == std::string::npos || !parse(all.substr(0, slash), shard.index) ||
      !parse(all.substr(slash + 1), shard.count) || shard.count < 1 || shard.index < 1 ||
      shard.index > shard.count)
    throw InputError("--shard '" + text + "' must be I/N with 1 <= I <= N (e.g. 2/4)");
  return shard;
}

int run_campaign_trials(const CampaignConfig& config, const std::vector<ObjectGroup>& groups,
                        const ArmLoops& loops, const std::vector<TrialJob>& jobs,
                        TrialJournal& journal, const CampaignRunOptions& options) {
  std::mutex report_mutex;
  int finished = 0;
  run_jobs(
      jobs.size(), options.workers,
      [&]() -> JobRunner {
        auto worker = std::make_shared<Worker>(loops);
        return [&, worker](std::size_t k) {
          const TrialJob& job = jobs[k];
          const std::optional<loop::Trial> trial =
              worker->run(job, group_seed(config.seed, groups.at(job.group)), options.stop);
          if (!trial) return false;
          // Trials are numbered by campaign id in every file (the runner numbers them within the
          // group).
          TrialResult result = records_of(*trial);
          result.record.trial = job.id;
          for (StepRecord& s : result.steps) s.trial = job.id;
          JournalEntry entry{job.id, config.arms[job.arm].name, groups[job.group].object,
                             trial_loop(loops, job).session, std::move(result)};
          journal.append(entry);
          std::lock_guard<std::mutex> lock(report_mutex);
          ++finished;
          if (options.on_trial) options.on_trial(entry);
          return true;
        };
      },
      options.stop);
  return finished;
}

}  // namespace echoplan::experiment
