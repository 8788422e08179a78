// libFuzzer target: arbitrary bytes as a problem file, through the YAML reader
// (common/yaml_reader.h, pomdp/problem_yaml.cpp) and the Cassandra .pomdp reader; a problem that
// loads is also checked. Bad input must end in echoplan::InputError; anything else (a crash, a
// sanitizer report, another exception, a hang) is a bug.
#include <cstddef>
#include <cstdint>
#include <string>

#include "common/error.h"
#include "pomdp/cassandra_reader.h"
#include "pomdp/problem.h"
#include "pomdp/problem_check.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const echoplan::pomdp::Problem problem = echoplan::pomdp::parse_problem_yaml(text, "fuzz.yaml");
    (void)echoplan::pomdp::check_problem(problem);
  } catch (const echoplan::InputError&) {
  }
  try {
    (void)echoplan::pomdp::parse_cassandra_pomdp(text, "fuzz.pomdp");
  } catch (const echoplan::InputError&) {
  }
  return 0;
}
