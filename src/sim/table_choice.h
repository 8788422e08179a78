// Which of the catalogue's tables a recording or a trial is made on: the sim config's `table:`
// (SimConfig::tables), none for the catalogue's default, one for every recording and trial, or a
// list.
//
// A list is spread over a recordings set evenly by recording index (recording i of each pair on
// table i mod n), so a training set covers every table as often as the others and does not depend
// on a draw; a trial draws its table from its own seed on a stream of its own, so every arm of a
// campaign, given the trial's seed, meets the same table and the trial's other draws (physics,
// sound) are those it would make on one table.
#pragma once

#include <cstdint>
#include <string>

#include "sim/catalogue.h"
#include "sim/sim_config.h"

namespace echoplan::sim {

// Throws InputError naming the catalogue when `config` names a table it does not have.
void check_tables(const Catalogue& catalogue, const SimConfig& config);

// The table of recording `index` of a pair: config.tables[index mod n], the default without any.
const TableSpec& table_of_recording(const Catalogue& catalogue, const SimConfig& config, int index);

// The name of the table of the trial seeded `trial_seed`: the only one named, or one of the list
// drawn uniformly from the trial's seed; empty (the default table) when the config names none.
std::string table_of_trial(const SimConfig& config, std::uint64_t trial_seed);

}  // namespace echoplan::sim
