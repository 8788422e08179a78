#include "commands/sim_options.h"

#include "sim/random_tables.h"
#include "sim/table_choice.h"

namespace echoplan::cli {

void add_sim_file_options(CLI::App& cmd, SimFiles& files) {
  cmd.add_option("--catalogue", files.catalogue,
                 "Object catalogue YAML (default: objects/catalogue.yaml here, else the one "
                 "shipped with echoplan)");
  cmd.add_option("--sim-config", files.config,
                 "Simulation config YAML: variability, microphone, room, recording, physics "
                 "(default: built-in)");
  cmd.add_option("--surface", files.surface,
                 "Table to act on, from the catalogue's tables (default: the sim config's, else "
                 "the lab's); a comma-separated list: spread over recordings, drawn per trial; "
                 "random:N: N tables drawn from --seed over the range real tops span "
                 "(docs/simulator.md)")
      ->delimiter(',');
}

SimSetup load_sim_setup(const SimFiles& files, std::uint64_t seed) {
  SimSetup setup{sim::load_catalogue(files.catalogue.empty() ? sim::default_catalogue_path()
                                                             : files.catalogue),
                 {}};
  if (!files.config.empty()) setup.config = sim::load_sim_config(files.config);
  if (!files.surface.empty())
    setup.config.tables = sim::expand_random_tables(setup.catalogue, files.surface, seed, "");
  sim::check_tables(setup.catalogue, setup.config);
  return setup;
}

loop::SimulatedWorldSpec load_simulated_world(const SimFiles& files, std::uint64_t seed) {
  SimSetup setup = load_sim_setup(files, seed);
  return {std::make_shared<const sim::Catalogue>(std::move(setup.catalogue)),
          std::make_shared<const sim::SimConfig>(std::move(setup.config))};
}

}  // namespace echoplan::cli
