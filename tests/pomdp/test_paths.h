// Repository files used by the pomdp tests: the shipped problems are the fixtures (no copies of
// their tables in tests).
#pragma once

#include <fstream>
#include <iterator>
#include <string>

#include "../common/source_dir.h"

namespace echoplan::pomdp::testing {

inline std::string repo_file(const std::string& relative) {
  return echoplan::testing::source_dir() + "/" + relative;
}

// The text of a repository file (empty if it cannot be read), for tests that edit a shipped
// problem.
inline std::string repo_text(const std::string& relative) {
  std::ifstream in(repo_file(relative), std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

}  // namespace echoplan::pomdp::testing
