// Reading the simulator's YAML files (catalogue, sim config): the text of a file and its parse
// tree, with failures as InputError naming the file (and, for a syntax error, the line).
#pragma once

#include <yaml-cpp/yaml.h>

#include <string>

namespace echoplan::sim {

// The whole text of `path`; throws InputError(path, 0, "cannot open the <what>") if it cannot be
// read.
std::string read_text_file(const std::string& path, const std::string& what);

// Parses YAML `text`; throws InputError(source, line, "not valid YAML: ...") on a syntax error.
YAML::Node parse_yaml(const std::string& text, const std::string& source);

}  // namespace echoplan::sim
