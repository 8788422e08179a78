#include "experiment/unheard_choice.h"

#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <memory>
#include <mutex>

#include "common/error.h"
#include "common/file_io.h"
#include "common/parallel_jobs.h"
#include "common/statistics.h"
#include "experiment/campaign_runner.h"
#include "experiment/expected_reward.h"
#include "experiment/trial_records.h"
#include "loop/loop.h"
#include "loop/planner.h"
#include "loop/streams.h"

namespace echoplan::experiment {

namespace {

constexpr solvers::UnheardOutcomes kEstimates[] = {solvers::UnheardOutcomes::share,
                                                   solvers::UnheardOutcomes::commit};

// The loop of each estimate (outer) and problem (inner): the problem is the world (a table world).
std::vector<std::vector<std::shared_ptr<const loop::LoopSpec>>> self_play_specs(
    const UnheardSelfPlay& play) {
  std::vector<std::vector<std::shared_ptr<const loop::LoopSpec>>> specs;
  for (solvers::UnheardOutcomes estimate : kEstimates) {
    auto& row = specs.emplace_back();
    for (const auto& problem : play.problems) {
      if (!problem->model->tabular() || problem->belief.type != pomdp::BeliefSettings::Type::exact)
        throw InputError(problem->source_path, 0,
                         "unheard: auto plays the problem as the world with an exact belief; "
                         "this problem has no table or no exact belief");
      loop::LoopSettings s;
      s.problem = problem;
      s.planner = play.planner;
      s.planner.unheard = solvers::unheard_outcomes_name(estimate);
      s.max_steps = play.max_steps;
      row.push_back(std::make_shared<const loop::LoopSpec>(std::move(s)));
    }
  }
  return specs;
}

}  // namespace

std::optional<UnheardChoice> choose_unheard(const UnheardSelfPlay& play, const ProgressFn& progress,
                                            const std::atomic<bool>& stop) {
  if (play.problems.empty() || play.trials < 2 || play.workers < 1)
    throw InputError(
        fmt::format("unheard: auto needs a problem, 2 or more trials and a worker "
                    "(given {} problems, {} trials, {} workers)",
                    play.problems.size(), play.trials, play.workers));
  const auto specs = self_play_specs(play);
  const int jobs = 2 * play.trials;  // job j: estimate j / trials, trial j % trials
  std::vector<std::vector<double>> expected(2, std::vector<double>(play.trials, 0.0));
  std::mutex mutex;
  int finished = 0;
  run_jobs(
      jobs, play.workers,
      [&]() -> JobRunner {
        // This thread's loops, one per spec it meets.
        auto loops = std::make_shared<std::map<const loop::LoopSpec*, loop::Loop>>();
        return [&, loops](std::size_t j) {
          const int e = static_cast<int>(j) / play.trials, t = static_cast<int>(j) % play.trials;
          const auto& spec = specs[e][t % play.problems.size()];
          auto it = loops->find(spec.get());
          if (it == loops->end()) it = loops->emplace(spec.get(), loop::Loop(spec)).first;
          const std::optional<loop::Trial> trial = it->second.run({t, -1, play.seed}, {}, &stop);
          if (!trial) return false;
          const std::optional<double> value = expected_discounted_reward(
              records_of(*trial).steps, *spec->problem().model->tabular());
          if (!value)
            throw std::logic_error("unheard: auto: a trial's belief does not fit its model");
          std::lock_guard<std::mutex> lock(mutex);
          expected[e][t] = *value;
          if (progress) progress("choose unheard", ++finished, jobs);
          return true;
        };
      },
      &stop);
  if (stop) return std::nullopt;

  std::vector<double> difference(play.trials);
  for (int t = 0; t < play.trials; ++t) difference[t] = expected[1][t] - expected[0][t];
  const MeanInterval d = mean_ci95(difference);
  UnheardChoice choice;
  choice.chosen = d.mean > 0.0 ? solvers::UnheardOutcomes::commit : solvers::UnheardOutcomes::share;
  choice.difference = d.mean;
  choice.ci95 = d.half_width;
  choice.trials = play.trials;
  return choice;
}

std::shared_ptr<const pomdp::Problem> with_exact_belief(
    const std::shared_ptr<const pomdp::Problem>& problem) {
  if (problem->belief.type == pomdp::BeliefSettings::Type::exact) return problem;
  auto exact = std::make_shared<pomdp::Problem>(*problem);
  exact->belief.type = pomdp::BeliefSettings::Type::exact;
  return exact;
}

bool choose_arms_unheard(const CampaignConfig& config, std::vector<ResolvedArm>& arms,
                         const ArmSelfPlayProblems& problems_of,
                         const std::filesystem::path& directory, const ProgressFn& progress,
                         const std::atomic<bool>& stop, int workers) {
  using Key = std::pair<std::vector<const pomdp::Problem*>, std::string>;  // problems and leaf
  std::map<Key, UnheardChoice> made;
  std::vector<ArmUnheardChoice> choices;
  for (std::size_t a = 0; a < arms.size(); ++a) {
    const ResolvedArm& arm = arms[a];
    if (!arm.unheard_by_play) continue;
    UnheardSelfPlay play;
    play.problems = problems_of(a);
    Key key{{}, arm.planner.leaf};
    for (const auto& p : play.problems) key.first.push_back(p.get());
    auto it = made.find(key);
    if (it == made.end()) {
      play.planner = arm.planner;
      play.trials = config.planner.self_play_trials;
      play.max_steps = config.planner.max_steps;
      play.seed = loop::stream_seed(config.seed, loop::Stream::campaign_unheard);
      play.workers = workers;
      const std::optional<UnheardChoice> choice = choose_unheard(play, progress, stop);
      if (!choice) return false;
      it = made.emplace(key, *choice).first;
    }
    choices.push_back({arm.name, it->second});
  }
  if (choices.empty()) return true;
  for (const ArmUnheardChoice& c : choices)
    for (ResolvedArm& arm : arms)
      if (arm.name == c.arm) arm.planner.unheard = solvers::unheard_outcomes_name(c.choice.chosen);
  write_unheard_choices(directory / kUnheardChoices, choices);
  return true;
}

void apply_unheard_choices(const nlohmann::json& choices, std::vector<ResolvedArm>& arms) {
  for (const nlohmann::json& c : choices)
    for (ResolvedArm& arm : arms)
      if (arm.unheard_by_play && arm.name == c["arm"].get<std::string>())
        arm.planner.unheard = c["chosen"].get<std::string>();
}

void write_unheard_choices(const std::filesystem::path& file,
                           const std::vector<ArmUnheardChoice>& choices) {
  nlohmann::json arms = nlohmann::json::array();
  for (const ArmUnheardChoice& c : choices)
    arms.push_back({{"arm", c.arm},
                    {"chosen", solvers::unheard_outcomes_name(c.choice.chosen)},
                    {"commit_minus_share", c.choice.difference},
                    {"ci95", c.choice.ci95},
                    {"self_play_trials", c.choice.trials}});
  const nlohmann::json j = {
      {"what",
       "each arm's unheard: auto, chosen by the expected reward per trial of commit minus share, "
       "paired, on the arm's own problems (a dataset world's folds) as the world "
       "(experiment/unheard_choice.h)"},
      {"arms", std::move(arms)}};
  write_file_atomically(file, j.dump(2) + "\n");
}

nlohmann::json read_unheard_choices(const std::filesystem::path& file) {
  const nlohmann::json j =
      nlohmann::json::parse(read_text_file(file.string(), "unheard choices"), nullptr, false);
  const auto fits = [](const nlohmann::json& a) {
    return a.is_object() && a.contains("arm") && a["arm"].is_string() && a.contains("chosen") &&
           a["chosen"].is_string() && a.contains("commit_minus_share") &&
           a["commit_minus_share"].is_number() && a.contains("ci95") && a["ci95"].is_number() &&
           a.contains("self_play_trials") && a["self_play_trials"].is_number_integer();
  };
  if (j.is_discarded() || !j.is_object() || !j.contains("arms") || !j["arms"].is_array() ||
      !std::all_of(j["arms"].begin(), j["arms"].end(), fits))
    throw InputError(file.string(), 0,
                     "is not a campaign's unheard choices (arms of arm, chosen, "
                     "commit_minus_share, ci95, self_play_trials); remove it to choose again");
  return j["arms"];
}

}  // namespace echoplan::experiment
