// load_problem(), parse_problem(): the reader for a problem file, chosen by its extension.
#include <string>

#include "common/file_io.h"
#include "common/yaml_reader.h"
#include "pomdp/cassandra_reader.h"
#include "pomdp/problem.h"

namespace echoplan::pomdp {

Problem load_problem(const std::string& path) {
  return parse_problem(read_text_file(path, "problem file (.yaml or .pomdp)"), path);
}

Problem parse_problem(const std::string& text, const std::string& path) {
  if (path.size() >= 6 && path.compare(path.size() - 6, 6, ".pomdp") == 0) {
    Problem p;
    p.model = parse_cassandra_pomdp(text, path);
    p.belief.type = BeliefSettings::Type::exact;
    p.source_path = path;
    return p;
  }
  return parse_problem_yaml(text, path);
}

}  // namespace echoplan::pomdp
