#include "sim/yaml_file.h"

#include <fstream>
#include <sstream>

#include "common/error.h"

namespace echoplan::sim {

std::string read_text_file(const std::string& path, const std::string& what) {
  std::ifstream in(path);
  if (!in) throw InputError(path, 0, "cannot open the " + what);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

YAML::Node parse_yaml(const std::string& text, const std::string& source) {
  try {
    return YAML::Load(text);
  } catch (const YAML::ParserException& e) {
    throw InputError(source, e.mark.line + 1, "not valid YAML: " + e.msg);
  }
}

}  // namespace echoplan::sim
