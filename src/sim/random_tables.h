// Tables drawn at random, for training a classifier that must hear tables it never heard (domain
// randomisation: Tobin et al. 2017, "Domain randomization for transferring deep neural networks
// from simulation to the real world"). A training set recorded on the catalogue's few tables
// learns what varies among them and no more: held out, the stiffest, the softest and the least
// damped top were heard as another object (docs/BENCHMARKS.md, "Other tables"). Recorded instead on
// many tables spread over the range real tops span, it learns which parts of a sound the table
// moves; and since each recording is on a table of its own, leave-one-out calibration already
// holds every table out.
//
// In any list of tables (`--surface`, a campaign's `world.surface` and `training_set.surfaces`)
// the entry `random:N` stands for N tables drawn from the seed, each through the physics every
// table acts through (catalogue.h, TableSpec). Ranges, uniform in the logarithm unless said
// (sources as the catalogue's own tables: Wood Handbook FPL-GTR-190, EN 572-1, Cremer, Heckl &
// Petersson's loss factors, engineering toolbox tables):
//   top's Young's modulus      2 to 220 GPa     fibreboard (MDF ~3.5) to steel (200-210)
//   top's density              500 to 8000      softwood to steel (kg/m^3)
//   top's Poisson ratio        0.20 to 0.35     uniform: glass to plastics
//   top's loss factor at 1 kHz 0.0004 to 0.05   steel plate to particle board; a fifth of it
//                                               mass-proportional (alpha), as the catalogue splits
//                                               it
//   top's thickness            5 to 40 mm       a steel bench's plate to a butcher block
//   a soft surface layer       3 in 10 tables   a mat, cork, linoleum on the top:
//     its modulus              2 MPa to 2 GPa   soft rubber to vinyl
//     its loss factor          0.05 to 0.4      hard to soft rubber; density 1200, Poisson 0.45
//   friction with the pad      0.4 to 0.9       uniform: wood on wood to rubber
// The contact loss is the catalogue's default table's, scaled by the top's point mobility over that
// table's (as every catalogue table's is); the dense modal field is the catalogue's (150 Hz - 8
// kHz, 32 modes).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "sim/catalogue.h"

namespace echoplan::sim {

// Table `index` (from 1) of the tables drawn from `seed` under `tag`, named `name`. The same seed,
// tag and index give the same table; `lab` is the catalogue's default table (its contact loss and
// dense field are the reference).
TableSpec random_table(std::uint64_t seed, const std::string& tag, int index,
                       const std::string& name, const TableSpec& lab);

// `names` with each entry `random:N` (N in 1..1000) replaced by N tables drawn from `seed` under
// `tag` and added to `catalogue`, named `<tag>_random_<i>` (`random_<i>` for an empty tag); other
// entries unchanged. Lists drawn under different tags hold different tables: a campaign draws its
// training set's and its world's apart. InputError for a malformed count.
std::vector<std::string> expand_random_tables(Catalogue& catalogue,
                                              const std::vector<std::string>& names,
                                              std::uint64_t seed, const std::string& tag);

}  // namespace echoplan::sim
