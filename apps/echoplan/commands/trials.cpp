// `echoplan trials`: run the plan-act-listen loop many times on a problem and log the results.
#include <fmt/core.h>
#include <spdlog/spdlog.h>

#include <chrono>
#include <nlohmann/json.hpp>

#include "commands/commands.h"
#include "commands/planner_options.h"
#include "common/error.h"
#include "common/stop_signal.h"
#include "experiment/expected_reward.h"
#include "experiment/trial_log.h"
#include "experiment/trial_records.h"
#include "experiment/trial_summary.h"
#include "loop/loop.h"
#include "pomdp/object_identification_model.h"
#include "pomdp/problem.h"
#include "solvers/strategy_measures.h"

namespace echoplan::cli {

namespace {

struct TrialsFlags {
  std::string problem;
  int trials = 40;
  int per_object = 0;
  int max_steps = 100;
  std::uint64_t seed = 1;
  std::string out;
  solvers::PlannerOverrides planner;
};

void print_summary(const experiment::TrialSummary& s, const pomdp::ModelSpec& spec,
                   const loop::Planner& planner, double seconds) {
  fmt::print("{:<24}{}\n", "problem", spec.name);
  fmt::print("{:<24}{}\n", "solver", planner.describe());
  fmt::print("{:<24}{}\n", "trials", s.trials);
  fmt::print("{:<24}{:.1f}%\n", "accuracy", 100.0 * s.accuracy);
  if (s.sorted_right) fmt::print("{:<24}{:.1f}%\n", "sorted right", 100.0 * *s.sorted_right);
  fmt::print("{:<24}{:.3f} ± {:.3f} (95% CI)\n", "mean discounted reward", s.mean_discounted_reward,
             s.ci95);
  if (s.expected_reward.n > 0)
    fmt::print("{:<24}{:.3f} ± {:.3f} (95% CI; each reward's expectation under the belief)\n",
               "expected reward", s.expected_reward.mean, s.expected_reward.half_width);
  fmt::print("{:<24}{:.2f}\n", "mean steps", s.mean_steps);
  for (std::size_t a = 0; a < spec.action_names.size(); ++a)
    fmt::print("{:<24}{:.2f}\n", "  mean " + spec.action_names[a], s.mean_action_counts[a]);
  if (s.collisions > 0) fmt::print("{:<24}{}\n", "collisions", s.collisions);
  if (s.capped > 0) fmt::print("{:<24}{}\n", "stopped by --max-steps", s.capped);
  fmt::print("{:<24}{:.1f} s\n", "wall time", seconds);
}

// Reports a finished trial on stderr.
void say_trial(const experiment::TrialRecord& t, const pomdp::ModelSpec& spec, int total) {
  const auto& names = spec.state.discrete_value_names;
  auto name = [&](int v) { return names.empty() ? std::to_string(v) : names[0][v]; };
  spdlog::info("trial {}/{}: true {}, believed {}, {} steps, discounted reward {:.3f}", t.trial + 1,
               total, name(t.true_state), name(t.believed_state), t.steps, t.discounted_reward);
}

// Per object, the sorting action right for it (its decision region; the first on ties), for an
// object problem; empty for other models.
std::vector<int> right_sorts(const pomdp::Problem& problem) {
  const pomdp::ObjectIdentificationModel* objects = problem.model->object_identification();
  if (objects == nullptr) return {};
  std::vector<int> right = solvers::decision_regions(objects->data());
  for (int& bin : right) bin += objects->num_sensing();
  return right;
}

void run_trials_command(const TrialsFlags& f) {
  loop::LoopSettings settings;
  settings.problem = std::make_shared<const pomdp::Problem>(pomdp::load_problem(f.problem));
  settings.planner = f.planner;
  settings.max_steps = f.max_steps;
  loop::Loop trials(std::make_shared<const loop::LoopSpec>(std::move(settings)));
  const pomdp::Problem& problem = trials.spec().problem();
  const loop::Planner& planner = trials.planner();

  loop::TrialOptions options;
  options.trials = f.trials;
  options.per_object = f.per_object;
  options.budget = planner.budget;
  options.max_steps = f.max_steps;
  options.validate();
  const pomdp::ModelSpec& spec = problem.model->spec();
  const int total = options.total_trials(spec);

  const int logged_particles =
      problem.belief.type == pomdp::BeliefSettings::Type::particle ? problem.belief.particles : 0;
  experiment::TrialLog log(f.out, spec, logged_particles);
  // Ctrl-C stops the runner between steps; finished trials and the summary are still written.
  const StopSignal stop;

  spdlog::info("{} trials of {} on {}, results in {}", total, planner.describe(), spec.name, f.out);
  const auto start = std::chrono::steady_clock::now();
  std::vector<experiment::TrialRecord> records;
  // With an exact belief the logged beliefs are the true state's distribution given the trial so
  // far (the model is the world), so rewards in expectation under them are a measure of the same
  // mean with less variance (experiment/expected_reward.h).
  const pomdp::TabularModel* tables = problem.model->tabular();
  const bool exact_belief = logged_particles == 0 && tables != nullptr;
  std::vector<double> expected;
  for (int t = 0; t < total; ++t) {
    const auto trial = trials.run({t, options.object_of_trial(t), f.seed}, {}, &stop.flag());
    if (!trial) break;
    const experiment::TrialResult result = experiment::records_of(*trial);
    log.trial_finished(result.record, result.steps);
    say_trial(result.record, spec, total);
    records.push_back(result.record);
    if (exact_belief)
      if (const auto value = experiment::expected_discounted_reward(result.steps, *tables))
        expected.push_back(*value);
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  experiment::TrialSummary summary = experiment::summarize(records, problem.model->num_actions());
  // Where bins are coarser than objects, the object believed at the end (accuracy) can be wrong
  // and the sort right: say both.
  if (const std::vector<int> right = right_sorts(problem); !right.empty())
    summary.sorted_right = experiment::share_right(records, right);
  if (!expected.empty() && expected.size() == records.size())
    summary.expected_reward = mean_ci95(expected);
  nlohmann::json run = planner.to_json();
  run.update({{"problem", f.problem},
              {"seed", f.seed},
              {"trials_requested", total},
              {"per_object", f.per_object},
              {"max_steps", f.max_steps},
              {"belief", logged_particles > 0 ? "particle" : "exact"},
              {"interrupted", stop.requested()}});
  log.write_summary(summary, run);
  if (summary.expected_reward.n > 0) log.write_expected_rewards(expected);
  print_summary(summary, spec, planner, seconds);
  if (stop.requested()) {
    spdlog::warn("interrupted: {} of {} trials finished and written to {}", records.size(), total,
                 f.out);
    throw Interrupted{};
  }
}

}  // namespace

void add_trials_command(CLI::App& app) {
  auto flags = std::make_shared<TrialsFlags>();
  auto* cmd = app.add_subcommand(
      "trials",
      "Run planning trials on a problem: the true object is drawn per trial, the solver plans "
      "each\n"
      "step, the model acts as the world. Writes DIR/trials.csv, DIR/steps.csv, DIR/summary.json\n"
      "and prints a summary. With an exact belief the summary also gives the expected reward\n"
      "(each reward's expectation under the belief it was chosen from: the same mean, less\n"
      "variance), per trial in DIR/expected_rewards.csv; runs with the same --seed draw the same\n"
      "true objects, so two solvers compare trial by trial.\n"
      "Example:\n"
      "  echoplan trials --problem problems/audio_objects.yaml --per-object 10 --episodes 2000 "
      "--seed 1 --out results/abt");
  cmd->add_option("--problem", flags->problem, "Problem file (.yaml or .pomdp)")->required();
  auto* trials =
      cmd->add_option("--trials", flags->trials, "Number of trials, true state drawn from b0")
          ->check(positive())
          ->capture_default_str();
  cmd->add_option("--per-object", flags->per_object,
                  "Instead of --trials: this many trials per object (the report used 10)")
      ->check(positive())
      ->excludes(trials);
  cmd->add_option("--max-steps", flags->max_steps, "Stop a trial after this many steps")
      ->capture_default_str();
  cmd->add_option("--seed", flags->seed, "Seed of every random choice")->capture_default_str();
  cmd->add_option("--out", flags->out, "Folder for trials.csv, steps.csv, summary.json")
      ->required();
  add_planner_options(*cmd, flags->planner);
  cmd->callback([flags] { run_trials_command(*flags); });
}

}  // namespace echoplan::cli
