// Parsing a JSON document from someone else (a model file, a policy file) with its nesting bounded.
//
// nlohmann 3.11 parses and frees any depth without recursing (10 million nested '[' load), but
// copying, comparing or dumping a value recurses: a copy of 100,000 nested arrays (a 200 KB file)
// overflows an 8 MiB stack. The readers do none of that with a file's values today; bounding the
// depth at the parse keeps it so whatever a reader does later. Real documents nest a handful of
// levels.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace echoplan {

// The deepest nesting of arrays and objects a JSON input may have (about this many levels: counted
// as nlohmann's parser callback counts depth).
inline constexpr int kMaxJsonDepth = 128;

// nlohmann::json::parse(text), except that nesting deeper than kMaxJsonDepth throws
// InputError(source, 0, ...) before it is built. Syntax errors and out-of-range numbers throw
// nlohmann's exceptions as parse does, so callers report them as before.
nlohmann::json parse_json(const std::string& text, const std::string& source);

}  // namespace echoplan
