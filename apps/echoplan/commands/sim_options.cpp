#include "commands/sim_options.h"

namespace echoplan::cli {

void add_sim_file_options(CLI::App& cmd, SimFiles& files) {
  cmd.add_option("--catalogue", files.catalogue,
                 "Object catalogue YAML (default: objects/catalogue.yaml here, else the one "
                 "shipped with echoplan)");
  cmd.add_option("--sim-config", files.config,
                 "Simulation config YAML: variability, microphone, room, recording, physics "
                 "(default: built-in)");
}

SimSetup load_sim_setup(const SimFiles& files) {
  SimSetup setup{sim::load_catalogue(files.catalogue.empty() ? sim::default_catalogue_path()
                                                             : files.catalogue),
                 {}};
  if (!files.config.empty()) setup.config = sim::load_sim_config(files.config);
  return setup;
}

loop::SimulatedWorldSpec load_simulated_world(const SimFiles& files) {
  SimSetup setup = load_sim_setup(files);
  return {std::make_shared<const sim::Catalogue>(std::move(setup.catalogue)),
          std::make_shared<const sim::SimConfig>(std::move(setup.config))};
}

}  // namespace echoplan::cli
