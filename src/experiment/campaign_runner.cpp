#include "experiment/campaign_runner.h"

#include <charconv>
#include <exception>
#include <map>
#include <mutex>
#include <thread>

#include "common/error.h"
#include "common/rng.h"
#include "common/stable_hash.h"
#include "pomdp/make_belief.h"
#include "pomdp/problem.h"

namespace echoplan::experiment {

namespace {

int object_index(const pomdp::Problem& problem, const std::string& object) {
  const auto& names = problem.model->spec().state.discrete_value_names;
  if (!names.empty())
    for (std::size_t v = 0; v < names[0].size(); ++v)
      if (names[0][v] == object) return static_cast<int>(v);
  throw InputError(problem.source_path, 0, "has no object '" + object + "'");
}

// What one worker owns: per arm a problem and a solver, per group a world.
class Worker {
 public:
  Worker(const CampaignConfig& config, const WorldFactory& world)
      : config_(config), world_(world) {}

  std::optional<TrialResult> run(const TrialJob& job, const std::atomic<bool>* stop) {
    Arm& arm = arm_for(job.arm);
    pomdp::Environment& environment = world_for(job.group);
    const ObjectGroup& group = config_.groups[job.group];

    TrialSetup setup;
    setup.model = arm.problem.model.get();
    setup.environment = &environment;
    setup.solver = arm.planner.solver.get();
    const pomdp::Problem& problem = arm.problem;
    setup.make_belief = [&problem](Rng& rng) { return pomdp::make_belief(problem, rng); };
    setup.stop_requested = stop;

    TrialOptions options;
    options.seed = group_seed(config_, job.group);
    options.max_steps = config_.planner.max_steps;
    options.budget = arm.planner.budget;
    return run_trial(setup, options, job.index, object_index(problem, group.plays));
  }

 private:
  struct Arm {
    pomdp::Problem problem;
    Planner planner;
  };

  Arm& arm_for(int index) {
    auto it = arms_.find(index);
    if (it != arms_.end()) return it->second;
    Arm arm;
    arm.problem = pomdp::load_problem(config_.arms[index].problem);
    arm.planner = make_arm_planner(config_, arm.problem);
    return arms_.emplace(index, std::move(arm)).first->second;
  }

  pomdp::Environment& world_for(int group) {
    auto it = worlds_.find(group);
    if (it == worlds_.end()) it = worlds_.emplace(group, world_(config_.groups[group])).first;
    return *it->second;
  }

  const CampaignConfig& config_;
  const WorldFactory& world_;
  std::map<int, Arm> arms_;
  std::map<int, std::unique_ptr<pomdp::Environment>> worlds_;
};

}  // namespace

Planner make_arm_planner(const CampaignConfig& config, const pomdp::Problem& problem) {
  solvers::PlannerOverrides overrides;
  overrides.solver = config.planner.solver;
  overrides.episodes = config.planner.episodes;
  overrides.step_ms = config.planner.step_ms;
  return make_planner(overrides, problem, problem.source_path);
}

std::vector<TrialJob> campaign_jobs(const CampaignConfig& config) {
  std::vector<TrialJob> jobs;
  int id = 0;
  for (int a = 0; a < static_cast<int>(config.arms.size()); ++a)
    for (int g = 0; g < static_cast<int>(config.groups.size()); ++g)
      for (int i = 0; i < config.groups[g].trials; ++i) jobs.push_back({id++, a, g, i});
  return jobs;
}

std::uint64_t group_seed(const CampaignConfig& config, int group) {
  return derive_seed(config.seed, {stable_hash(config.groups[group].object)});
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

int run_campaign_trials(const CampaignConfig& config, const std::vector<TrialJob>& jobs,
                        const WorldFactory& world, TrialJournal& journal,
                        const CampaignRunOptions& options) {
  std::atomic<std::size_t> next{0};
  std::atomic<int> finished{0};
  std::atomic<bool> failed{false};
  std::exception_ptr first_error;
  std::mutex report_mutex;
  auto stopped = [&] { return failed.load() || (options.stop && options.stop->load()); };

  auto work = [&] {
    try {
      Worker worker(config, world);
      while (!stopped()) {
        const std::size_t k = next.fetch_add(1);
        if (k >= jobs.size()) break;
        const TrialJob& job = jobs[k];
        std::optional<TrialResult> result = worker.run(job, options.stop);
        if (!result) break;
        // Trials are numbered by campaign id in every file (the runner numbers them within the
        // group).
        result->record.trial = job.id;
        for (StepRecord& s : result->steps) s.trial = job.id;
        JournalEntry entry{job.id, config.arms[job.arm].name, config.groups[job.group].object,
                           std::move(*result)};
        journal.append(entry);
        std::lock_guard<std::mutex> lock(report_mutex);
        ++finished;
        if (options.on_trial) options.on_trial(entry);
      }
    } catch (...) {
      std::lock_guard<std::mutex> lock(report_mutex);
      if (!first_error) first_error = std::current_exception();
      failed = true;
    }
  };

  const int workers = std::max(1, std::min<int>(options.workers, static_cast<int>(jobs.size())));
  std::vector<std::thread> threads;
  for (int w = 1; w < workers; ++w) threads.emplace_back(work);
  work();
  for (std::thread& t : threads) t.join();
  if (first_error) std::rethrow_exception(first_error);
  return finished.load();
}

}  // namespace echoplan::experiment
