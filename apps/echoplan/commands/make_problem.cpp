// `echoplan make-problem`: write a random object-identification problem for scale studies.
#include <fmt/core.h>
#include <spdlog/spdlog.h>

#include <fstream>
#include <stdexcept>

#include "commands/commands.h"
#include "common/error.h"
#include "common/rng.h"
#include "pomdp/problem.h"
#include "pomdp/random_problem.h"

namespace echoplan::cli {

void add_make_problem_command(CLI::App& app) {
  struct Options {
    pomdp::RandomProblemSettings settings;
    std::string output;
  };
  auto options = std::make_shared<Options>();
  auto* cmd = app.add_subcommand(
      "make-problem",
      "Write a random object-identification problem (YAML) with N objects, M sensing actions and\n"
      "J sorting bins.\n"
      "Observation rows are Dirichlet draws with more mass on the true class; the objects are "
      "split\n"
      "at random among the bins. The same seed writes the same file.");
  cmd->add_option("--objects", options->settings.objects, "Number of objects (2-1000)")->required();
  cmd->add_option("--sensing-actions", options->settings.sensing_actions,
                  "Number of sensing actions (1-100)")
      ->required();
  cmd->add_option("--seed", options->settings.seed, "Random seed")->required();
  cmd->add_option("--bins", options->settings.bins,
                  "Number of sorting actions (bins A, B, ...), 2 to 26; objects split evenly")
      ->capture_default_str();
  cmd->add_option("--concentration", options->settings.concentration,
                  "Diagonal weight C: the right class is heard with probability C/(C+1) on average")
      ->capture_default_str();
  cmd->add_option("-o,--output", options->output, "YAML file to write")->required();
  cmd->callback([options] {
    Rng rng(derive_seed(options->settings.seed, {0x6d616b65}));  // stream "make"
    pomdp::ObjectProblemData data;
    try {
      data = pomdp::make_random_object_problem(options->settings, rng);
    } catch (const std::invalid_argument& e) {
      throw InputError(e.what());
    }
    std::ofstream out(options->output);
    if (!out) throw InputError(options->output, 0, "cannot write the problem file");
    out << "# Written by: echoplan make-problem --objects " << options->settings.objects
        << " --sensing-actions " << options->settings.sensing_actions << " --seed "
        << options->settings.seed << " --concentration " << options->settings.concentration
        << " --bins " << options->settings.bins << "\n";
    pomdp::write_problem_yaml(out, data, pomdp::BeliefSettings{}, pomdp::PlannerDefaults{});
    out.close();
    if (!out) throw InputError(options->output, 0, "could not finish writing the problem file");
    fmt::print("wrote {} ({} objects, {} sensing actions, {} bins)\n", options->output,
               data.objects.size(), data.sensing.size(), data.sorting.size());
  });
}

}  // namespace echoplan::cli
