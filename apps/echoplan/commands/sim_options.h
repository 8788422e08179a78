// Options shared by the simulator's commands (synth, dataset): which catalogue and sim config to
// use.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "loop/world_spec.h"
#include "sim/catalogue.h"
#include "sim/sim_config.h"

namespace echoplan::cli {

struct SimFiles {
  std::string catalogue;  // empty: sim::default_catalogue_path()
  std::string config;     // empty: built-in defaults
};

struct SimSetup {
  sim::Catalogue catalogue;
  sim::SimConfig config;
};

// Adds --catalogue and --sim-config to `cmd`.
void add_sim_file_options(CLI::App& cmd, SimFiles& files);

// Loads both; throws InputError for a bad file.
SimSetup load_sim_setup(const SimFiles& files);
// The same as a loop's simulated world (shared, read-only).
loop::SimulatedWorldSpec load_simulated_world(const SimFiles& files);

}  // namespace echoplan::cli
