// Paths of repository files used by the pomdp tests.
#pragma once

#include <string>

namespace echoplan::pomdp::testing {

inline std::string repo_file(const std::string& relative) {
  return std::string(ECHOPLAN_SOURCE_DIR) + "/" + relative;
}

}  // namespace echoplan::pomdp::testing
