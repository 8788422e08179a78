#include "commands/planner_options.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <exception>
#include <string>

#include "solvers/baseline_strategies.h"
#include "solvers/search_tree.h"

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

void add_planner_options(CLI::App& cmd, solvers::PlannerOverrides& f) {
  cmd.add_option("--solver", f.solver,
                 fmt::format("abt, pomcp, offline, or a baseline strategy: {} (default: the "
                             "problem file's; docs/planning.md)",
                             fmt::join(solvers::strategy_names(), ", ")));
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
                 "Leaf value: policy, exact or exact-offline (ABT only, identification problems), "
                 "lookahead, heuristic or rollout (default: policy for ABT on an identification "
                 "problem, else lookahead; docs/planning.md)");
  cmd.add_option("--unheard", f.unheard,
                 "ABT with leaf policy/exact: how a sensing action's outcomes no episode has heard "
                 "yet count: share (the heard outcomes' values, in proportion; the default) or "
                 "commit (the value of sorting right after them, a lower bound; docs/planning.md)")
      ->check(CLI::IsMember(solvers::unheard_outcomes_names()));
  cmd.add_option("--exact-share", f.exact_share,
                 "--leaf exact/exact-offline: share of each step's budget spent refining the exact "
                 "solver at the current belief before the episodes, in [0, 1]")
      ->capture_default_str();
  cmd.add_option("--offline-expansions", f.offline_expansions,
                 "--leaf exact-offline: node expansions of the exact solve made once before the "
                 "first step")
      ->capture_default_str();
  cmd.add_option("--expand-after", f.expand_after,
                 "Visits a new node is valued as a leaf before it branches")
      ->capture_default_str();
  cmd.add_option("--root-particles", f.root_particles,
                 "Particles drawn into the search root (default: the problem's belief size)");
  cmd.add_option("--branch-threshold", f.branch_threshold,
                 "Continuous observations closer than this share a branch")
      ->capture_default_str();
}

}  // namespace echoplan::cli
