#include "sim/table_choice.h"

#include "common/rng.h"

namespace echoplan::sim {

namespace {

// The trial's table stream under its seed ("surfa"), apart from the world's physics and sound.
constexpr std::uint64_t kTableStream = 0x7375726661;

}  // namespace

void check_tables(const Catalogue& catalogue, const SimConfig& config) {
  for (const std::string& name : config.tables) catalogue.table_named(name);
}

const TableSpec& table_of_recording(const Catalogue& catalogue, const SimConfig& config,
                                    int index) {
  if (config.tables.empty()) return catalogue.table;
  const auto n = static_cast<int>(config.tables.size());
  return catalogue.table_named(config.tables[static_cast<std::size_t>(index % n)]);
}

std::string table_of_trial(const SimConfig& config, std::uint64_t trial_seed) {
  if (config.tables.empty()) return {};
  if (config.tables.size() == 1) return config.tables.front();
  Rng rng(derive_seed(trial_seed, {kTableStream}));
  const auto k =
      static_cast<std::size_t>(uniform01(rng) * static_cast<double>(config.tables.size()));
  return config.tables[std::min(k, config.tables.size() - 1)];
}

}  // namespace echoplan::sim
