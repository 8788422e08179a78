// A campaign's input files, each read once: a problem is parsed from the same text its
// fingerprint in the campaign's identity is taken from.
#pragma once

#include <map>
#include <memory>
#include <string>

#include "pomdp/problem.h"

namespace echoplan::experiment {

class InputFiles {
 public:
  // The file's text (InputError naming it when it cannot be read).
  const std::string& text(const std::string& path);
  // The problem in the file, parsed once.
  std::shared_ptr<const pomdp::Problem> problem(const std::string& path);

 private:
  std::map<std::string, std::string> texts_;
  std::map<std::string, std::shared_ptr<const pomdp::Problem>> problems_;
};

}  // namespace echoplan::experiment
