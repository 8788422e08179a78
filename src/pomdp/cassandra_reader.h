// Reader for Cassandra's `.pomdp` text format (pomdp.org, SARSOP, APPL).
//
// Supported: `discount:`, `values: reward|cost`, `states:` / `actions:` / `observations:` as a
// count or a list of names, `start:` as a distribution, `uniform`, a single state, or the `start
// include:` / `start exclude:` forms; `T:`, `O:` and `R:` lines with names, indices or `*`
// wildcards in their single-entry, row and matrix forms; the `identity` and `uniform` keywords; `#`
// comments. Later lines overwrite earlier ones where they overlap. R(a, s, s', o) entries are
// folded into the expected reward R(s, a) = sum over s', o of T(s, a, s') O(a, s', o) R(a, s, s',
// o). Names are generated as s0, s1, ... (a0..., o0...) when a count is given.
#pragma once

#include <memory>
#include <string>

#include "pomdp/tabular_pomdp.h"

namespace echoplan::pomdp {

// Parses the text of a .pomdp file. `source_name` appears in errors. Throws InputError(file, line,
// problem) for malformed text, unknown names, wrong value counts, and rows that do not sum to 1
// (tolerance 1e-6).
std::shared_ptr<const TabularPomdp> parse_cassandra_pomdp(const std::string& text,
                                                          const std::string& source_name);

}  // namespace echoplan::pomdp
