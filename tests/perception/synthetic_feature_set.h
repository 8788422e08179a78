// The tests' names for the synthetic feature sets (the generator is
// perception/synthetic_feature_set.h, shared with bench/make_feature_set), and a fresh temporary
// folder to write them into.
#pragma once

#include <unistd.h>

#include <filesystem>
#include <string>

#include "perception/synthetic_feature_set.h"

namespace echoplan::perception::test_features {

using perception::SyntheticModality;
using perception::SyntheticSpec;
using perception::write_synthetic_feature_set;

inline std::string object_name(int o) { return synthetic_object_name(o); }
inline std::string group_name(int g) { return synthetic_group_name(g); }

// A fresh empty folder under the system's temporary folder.
inline std::filesystem::path fresh_folder(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("echoplan_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace echoplan::perception::test_features
