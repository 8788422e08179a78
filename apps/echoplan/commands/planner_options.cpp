#include "commands/planner_options.h"

#include <fmt/core.h>
#include <spdlog/spdlog.h>

#include "common/error.h"
#include "solvers/make_solver.h"
#include "solvers/offline/offline_policy_solver.h"

namespace echoplan::cli {

CLI::Validator positive() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        try {
          std::size_t used = 0;
          if (std::stod(text, &used) > 0.0 && used == text.size()) return "";
        } catch (const std::exception&) {
        }
        return "must be a number greater than 0, got " + text;
      },
      "> 0");
}

void add_planner_options(CLI::App& cmd, PlannerFlags& f) {
  cmd.add_option("--solver", f.solver, "abt, pomcp or offline (default: the problem file's)");
  cmd.add_option("--policy", f.policy,
                 "--solver offline: policy.json from `echoplan solve --out` (else solved now)");
  auto* episodes = cmd.add_option("--episodes", f.episodes,
                                  "Search episodes per step (reproducible bit for bit; default: "
                                  "the problem file's budget)")
                       ->check(positive());
  auto* step_ms =
      cmd.add_option("--step-ms", f.step_ms, "Search wall time per step, ms")->check(positive());
  episodes->excludes(step_ms);
  cmd.add_option("--exploration", f.exploration,
                 "UCB exploration constant c, reward units (default: the problem file's)");
  cmd.add_option("--depth", f.depth, "Maximum search depth (default: the problem file's)");
  cmd.add_option("--leaf", f.leaf,
                 "Leaf value: policy (ABT only), lookahead, heuristic or rollout (default: policy "
                 "for ABT on an identification problem, else lookahead)");
  cmd.add_option("--expand-after", f.expand_after,
                 "Visits a new node is valued as a leaf before it branches")
      ->capture_default_str();
  cmd.add_option("--root-particles", f.root_particles,
                 "Particles drawn into the search root (default: the problem's belief size)");
  cmd.add_option("--branch-threshold", f.branch_threshold,
                 "Continuous observations closer than this share a branch")
      ->capture_default_str();
}

namespace {

solvers::SearchOptions search_options(const PlannerFlags& f, const pomdp::Problem& problem,
                                      const std::string& solver) {
  solvers::SearchOptions o;
  o.exploration = f.exploration >= 0 ? f.exploration : problem.planner.exploration;
  o.max_depth = f.depth >= 0 ? f.depth : problem.planner.depth;
  o.leaf.mode = f.leaf.empty() ? solvers::default_leaf_mode(solver, *problem.model)
                               : solvers::parse_leaf_mode(f.leaf);
  o.leaf.expand_after = f.expand_after;
  o.root_particles = f.root_particles >= 0 ? f.root_particles : problem.belief.particles;
  o.branching.continuous_threshold = f.branch_threshold;
  o.validate();
  return o;
}

solvers::Budget budget(const PlannerFlags& f, const pomdp::Problem& problem) {
  if (f.episodes > 0) return solvers::Budget::episodes(f.episodes);
  if (f.step_ms > 0) return solvers::Budget::milliseconds(f.step_ms);
  if (problem.planner.episodes > 0) return solvers::Budget::episodes(problem.planner.episodes);
  return solvers::Budget::milliseconds(static_cast<std::int64_t>(problem.planner.step_ms));
}

}  // namespace

Planner make_planner(const PlannerFlags& f, const pomdp::Problem& problem,
                     const std::string& problem_path) {
  Planner p;
  p.name = f.solver.empty() ? problem.planner.solver : f.solver;
  if (!f.policy.empty() && p.name != "offline")
    throw InputError("--policy is for --solver offline; the " + p.name +
                     " solver plans online and would ignore it");
  p.options = search_options(f, problem, p.name);
  p.budget = budget(f, problem);
  if (p.name == "offline") {
    // The policy file when given, else the point-based solver run now (to its default precision or
    // time limit).
    if (f.policy.empty())
      spdlog::warn(
          "no --policy given: solving {} offline now, for up to {} s (save a policy once with "
          "`echoplan solve --method point-based --out DIR` and pass --policy DIR/policy.json)",
          problem_path, solvers::offline::SolverOptions{}.time_limit_seconds);
    p.solver = solvers::offline::make_offline_solver(problem.model, {}, f.policy, problem_path);
  } else {
    p.solver = solvers::make_solver(p.name, problem.model, p.options);
  }
  return p;
}

std::string Planner::describe() const {
  return budget.kind == solvers::Budget::Kind::episodes
             ? fmt::format("{}, {} episodes/step", name, budget.amount)
             : fmt::format("{}, {} ms/step", name, budget.amount);
}

nlohmann::json Planner::to_json() const {
  return {
      {"solver", name},
      {"budget",
       {{budget.kind == solvers::Budget::Kind::episodes ? "episodes" : "step_ms", budget.amount}}},
      {"search",
       {{"exploration", options.exploration},
        {"max_depth", options.max_depth},
        {"leaf", solvers::leaf_mode_name(options.leaf.mode)},
        {"expand_after", options.leaf.expand_after},
        {"root_particles", options.root_particles},
        {"branch_threshold", options.branching.continuous_threshold}}}};
}

}  // namespace echoplan::cli
