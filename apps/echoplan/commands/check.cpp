// `echoplan check`: load a problem, summarise it, and report likely mistakes with their fixes.
#include <fmt/core.h>

#include "commands/commands.h"
#include "pomdp/problem.h"
#include "pomdp/problem_check.h"

namespace echoplan::cli {

void add_check_command(CLI::App& app) {
  auto path = std::make_shared<std::string>();
  auto* cmd = app.add_subcommand("check",
                                 "Load a problem (YAML or .pomdp), print its size, and report "
                                 "likely mistakes with how to fix them.\n"
                                 "Findings are printed as warnings (exit status 0); a file that "
                                 "does not load exits with status 2.");
  cmd->add_option("--problem", *path, "Problem file (problems/*.yaml or *.pomdp)")->required();
  cmd->callback([path] {
    const pomdp::Problem problem = pomdp::load_problem(*path);
    const pomdp::ModelSpec& spec = problem.model->spec();
    fmt::print("{}: '{}', {} actions, {} observation symbols, discount {}\n", *path, spec.name,
               spec.action_names.size(), spec.observation.names.size(), spec.discount);
    if (const pomdp::TabularModel* t = problem.model->tabular()) {
      fmt::print("  tables: {} states, {} actions, {} observations\n", t->num_states(),
                 t->num_actions(), t->num_observations());
    }
    const bool exact = problem.belief.type == pomdp::BeliefSettings::Type::exact;
    fmt::print("  belief: {}\n", exact ? std::string("exact")
                                       : fmt::format("particle ({})", problem.belief.particles));
    fmt::print("  planner: {}, {}, depth {}, exploration {}\n", problem.planner.solver,
               problem.planner.episodes > 0
                   ? fmt::format("{} episodes/step", problem.planner.episodes)
                   : fmt::format("{} ms/step", problem.planner.step_ms),
               problem.planner.depth, problem.planner.exploration);
    const std::vector<std::string> findings = pomdp::check_problem(problem);
    if (findings.empty()) {
      fmt::print("ok: no problems found\n");
      return;
    }
    for (const auto& f : findings) fmt::print("warning: {}\n", f);
  });
}

}  // namespace echoplan::cli
