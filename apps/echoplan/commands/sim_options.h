// Options shared by the simulator's commands (synth, dataset): which catalogue and sim config to
// use.
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <string>
#include <vector>

#include "loop/world_spec.h"
#include "sim/catalogue.h"
#include "sim/sim_config.h"

namespace echoplan::cli {

struct SimFiles {
  std::string catalogue;  // empty: sim::default_catalogue_path()
  std::string config;     // empty: built-in defaults
  // --surface: the catalogue tables to record on, comma-separated (the sim config's `table:`);
  // empty: the sim config's.
  std::vector<std::string> surface;
};

struct SimSetup {
  sim::Catalogue catalogue;
  sim::SimConfig config;
};

// Adds --catalogue, --sim-config and --surface to `cmd`.
void add_sim_file_options(CLI::App& cmd, SimFiles& files);

// Loads both, with --surface as the config's tables, its `random:N` entries drawn from `seed`
// (sim/random_tables.h); throws InputError for a bad file or a table the catalogue does not have.
SimSetup load_sim_setup(const SimFiles& files, std::uint64_t seed);
// The same as a loop's simulated world (shared, read-only).
loop::SimulatedWorldSpec load_simulated_world(const SimFiles& files, std::uint64_t seed);

}  // namespace echoplan::cli
