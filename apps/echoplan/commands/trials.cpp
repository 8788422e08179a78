// `echoplan trials`: run the plan-act-listen loop many times on a problem and log the results.
#include <fmt/core.h>
#include <spdlog/spdlog.h>

#include <chrono>
#include <nlohmann/json.hpp>

#include "commands/commands.h"
#include "common/error.h"
#include "common/stop_signal.h"
#include "experiment/trial_log.h"
#include "experiment/trial_runner.h"
#include "experiment/trial_summary.h"
#include "pomdp/make_belief.h"
#include "pomdp/model_environment.h"
#include "pomdp/problem.h"
#include "solvers/leaf_value.h"
#include "solvers/make_solver.h"
#include "solvers/offline/offline_policy_solver.h"

namespace echoplan::cli {

namespace {

struct TrialsFlags {
  std::string problem;
  std::string solver;
  int trials = 40;
  int per_object = 0;
  std::int64_t episodes = 0;
  std::int64_t step_ms = 0;
  int max_steps = 100;
  std::uint64_t seed = 1;
  std::string out;
  // Search options; a negative or empty value means "the problem file's (or the built-in) default".
  double exploration = -1;
  int depth = -1;
  std::string leaf = "lookahead";
  int expand_after = solvers::LeafOptions{}.expand_after;
  int root_particles = -1;
  double branch_threshold = 0.0;
  std::string policy;  // --solver offline: alpha vectors from `echoplan solve --out`
};

// `--solver offline`: the policy file when given, else the point-based solver run now (to its
// default precision or time limit).
std::unique_ptr<solvers::Solver> offline_solver(const TrialsFlags& f, const pomdp::Problem& problem) {
  if (f.policy.empty()) spdlog::info("solving {} offline (no --policy given)", f.problem);
  return solvers::offline::make_offline_solver(problem.model, {}, f.policy, f.problem);
}

solvers::SearchOptions search_options(const TrialsFlags& f, const pomdp::Problem& problem) {
  solvers::SearchOptions o;
  o.exploration = f.exploration >= 0 ? f.exploration : problem.planner.exploration;
  o.max_depth = f.depth >= 0 ? f.depth : problem.planner.depth;
  o.leaf.mode = solvers::parse_leaf_mode(f.leaf);
  o.leaf.expand_after = f.expand_after;
  o.root_particles = f.root_particles >= 0 ? f.root_particles : problem.belief.particles;
  o.branching.continuous_threshold = f.branch_threshold;
  o.validate();
  return o;
}

solvers::Budget budget(const TrialsFlags& f, const pomdp::Problem& problem) {
  if (f.episodes > 0) return solvers::Budget::episodes(f.episodes);
  if (f.step_ms > 0) return solvers::Budget::milliseconds(f.step_ms);
  if (problem.planner.episodes > 0) return solvers::Budget::episodes(problem.planner.episodes);
  return solvers::Budget::milliseconds(static_cast<std::int64_t>(problem.planner.step_ms));
}

std::string budget_text(const solvers::Budget& b) {
  return b.kind == solvers::Budget::Kind::episodes ? fmt::format("{} episodes/step", b.amount)
                                                   : fmt::format("{} ms/step", b.amount);
}

void print_summary(const experiment::TrialSummary& s, const pomdp::ModelSpec& spec,
                   const std::string& solver, const solvers::Budget& b, double seconds) {
  fmt::print("{:<24}{}\n", "problem", spec.name);
  fmt::print("{:<24}{}, {}\n", "solver", solver, budget_text(b));
  fmt::print("{:<24}{}\n", "trials", s.trials);
  fmt::print("{:<24}{:.1f}%\n", "accuracy", 100.0 * s.accuracy);
  fmt::print("{:<24}{:.3f} ± {:.3f} (95% CI)\n", "mean discounted reward", s.mean_discounted_reward,
             s.ci95);
  fmt::print("{:<24}{:.2f}\n", "mean steps", s.mean_steps);
  for (std::size_t a = 0; a < spec.action_names.size(); ++a)
    fmt::print("{:<24}{:.2f}\n", "  mean " + spec.action_names[a], s.mean_action_counts[a]);
  if (s.collisions > 0) fmt::print("{:<24}{}\n", "collisions", s.collisions);
  if (s.capped > 0) fmt::print("{:<24}{}\n", "stopped by --max-steps", s.capped);
  fmt::print("{:<24}{:.1f} s\n", "wall time", seconds);
}

// Reports each finished trial on stderr and forwards it to the log.
class ProgressLog final : public experiment::TrialObserver {
 public:
  ProgressLog(experiment::TrialLog& log, const pomdp::ModelSpec& spec, int total)
      : log_(log), spec_(spec), total_(total) {}
  void trial_finished(const experiment::TrialRecord& t,
                      const std::vector<experiment::StepRecord>& steps) override {
    log_.trial_finished(t, steps);
    const auto& names = spec_.state.discrete_value_names;
    auto name = [&](int v) { return names.empty() ? std::to_string(v) : names[0][v]; };
    spdlog::info("trial {}/{}: true {}, believed {}, {} steps, discounted reward {:.3f}", t.trial + 1,
                 total_, name(t.true_state), name(t.believed_state), t.steps, t.discounted_reward);
  }

 private:
  experiment::TrialLog& log_;
  const pomdp::ModelSpec& spec_;
  int total_;
};

void run_trials_command(const TrialsFlags& f) {
  const pomdp::Problem problem = pomdp::load_problem(f.problem);
  const std::string solver_name = f.solver.empty() ? problem.planner.solver : f.solver;
  const solvers::SearchOptions options = search_options(f, problem);
  auto solver = solver_name == "offline" ? offline_solver(f, problem)
                                          : solvers::make_solver(solver_name, problem.model, options);
  pomdp::ModelEnvironment environment(problem.model);

  experiment::TrialOptions trial_options;
  trial_options.trials = f.trials;
  trial_options.per_object = f.per_object;
  trial_options.budget = budget(f, problem);
  trial_options.max_steps = f.max_steps;
  trial_options.seed = f.seed;
  trial_options.validate();
  const pomdp::ModelSpec& spec = problem.model->spec();
  const int total = trial_options.total_trials(spec);

  const int logged_particles =
      problem.belief.type == pomdp::BeliefSettings::Type::particle ? problem.belief.particles : 0;
  experiment::TrialLog log(f.out, spec, logged_particles);
  ProgressLog progress(log, spec, total);

  experiment::TrialSetup setup;
  setup.model = problem.model.get();
  setup.environment = &environment;
  setup.solver = solver.get();
  setup.make_belief = [&problem](Rng& rng) { return pomdp::make_belief(problem, rng); };
  // Ctrl-C stops the runner between steps; finished trials and the summary are still written.
  const StopSignal stop;
  setup.stop_requested = &stop.flag();

  spdlog::info("{} trials of {} on {} ({}), results in {}", total, solver_name, spec.name,
               budget_text(trial_options.budget), f.out);
  const auto start = std::chrono::steady_clock::now();
  const auto records = experiment::run_trials(setup, trial_options, progress);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  const experiment::TrialSummary summary = experiment::summarize(records, problem.model->num_actions());
  nlohmann::json run = {
      {"problem", f.problem},
      {"solver", solver_name},
      {"budget", {{trial_options.budget.kind == solvers::Budget::Kind::episodes ? "episodes" : "step_ms",
                   trial_options.budget.amount}}},
      {"seed", f.seed},
      {"trials_requested", total},
      {"per_object", f.per_object},
      {"max_steps", f.max_steps},
      {"belief", logged_particles > 0 ? "particle" : "exact"},
      {"search",
       {{"exploration", options.exploration},
        {"max_depth", options.max_depth},
        {"leaf", solvers::leaf_mode_name(options.leaf.mode)},
        {"expand_after", options.leaf.expand_after},
        {"root_particles", options.root_particles},
        {"branch_threshold", options.branching.continuous_threshold}}},
      {"interrupted", stop.requested()}};
  log.write_summary(summary, run);
  print_summary(summary, spec, solver_name, trial_options.budget, seconds);
  if (stop.requested()) {
    spdlog::warn("interrupted: {} of {} trials finished and written to {}", records.size(), total, f.out);
    throw Interrupted{};
  }
}

}  // namespace

void add_trials_command(CLI::App& app) {
  auto flags = std::make_shared<TrialsFlags>();
  auto* cmd = app.add_subcommand(
      "trials",
      "Run planning trials on a problem: the true object is drawn per trial, the solver plans each\n"
      "step, the model acts as the world. Writes DIR/trials.csv, DIR/steps.csv, DIR/summary.json\n"
      "and prints a summary. Example:\n"
      "  echoplan trials --problem problems/audio_objects.yaml --per-object 10 --episodes 2000 "
      "--seed 1 --out results/abt");
  cmd->add_option("--problem", flags->problem, "Problem file (.yaml or .pomdp)")->required();
  cmd->add_option("--solver", flags->solver, "abt, pomcp or offline (default: the problem file's)");
  cmd->add_option("--policy", flags->policy,
                  "--solver offline: policy.json from `echoplan solve --out` (else solved now)");
  cmd->add_option("--trials", flags->trials, "Number of trials, true state drawn from b0")
      ->capture_default_str();
  cmd->add_option("--per-object", flags->per_object,
                  "Instead of --trials: this many trials per object (the seed used 10)");
  auto* episodes = cmd->add_option("--episodes", flags->episodes,
                                   "Search episodes per step (reproducible bit for bit)");
  auto* step_ms = cmd->add_option("--step-ms", flags->step_ms, "Search wall time per step, ms");
  episodes->excludes(step_ms);
  cmd->add_option("--max-steps", flags->max_steps, "Stop a trial after this many steps")
      ->capture_default_str();
  cmd->add_option("--seed", flags->seed, "Seed of every random choice")->capture_default_str();
  cmd->add_option("--out", flags->out, "Folder for trials.csv, steps.csv, summary.json")->required();
  cmd->add_option("--exploration", flags->exploration,
                  "UCB exploration constant c, reward units (default: the problem file's)");
  cmd->add_option("--depth", flags->depth, "Maximum search depth (default: the problem file's)");
  cmd->add_option("--leaf", flags->leaf, "Leaf value: lookahead, heuristic or rollout")
      ->capture_default_str();
  cmd->add_option("--expand-after", flags->expand_after,
                  "Visits a new node is valued as a leaf before it branches")
      ->capture_default_str();
  cmd->add_option("--root-particles", flags->root_particles,
                  "Particles drawn into the search root (default: the problem's belief size)");
  cmd->add_option("--branch-threshold", flags->branch_threshold,
                  "Continuous observations closer than this share a branch")
      ->capture_default_str();
  cmd->callback([flags] { run_trials_command(*flags); });
}

}  // namespace echoplan::cli
