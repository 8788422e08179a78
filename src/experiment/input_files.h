// A campaign's input files and folders, each read once: a problem is parsed from the same text its
// fingerprint in the campaign's identity is taken from, and a dataset world's data is loaded once
// and fingerprinted as loaded.
#pragma once

#include <map>
#include <memory>
#include <string>

#include "common/progress.h"
#include "perception/feature_set.h"
#include "pomdp/problem.h"

namespace echoplan::experiment {

class InputFiles {
 public:
  // The file's text (InputError naming it when it cannot be read).
  const std::string& text(const std::string& path);
  // The problem in the file, parsed once.
  std::shared_ptr<const pomdp::Problem> problem(const std::string& path);
  // The data in `folder` (a feature set or a recordings tree: perception::load_data), loaded once.
  std::shared_ptr<const perception::FeatureSet> data(const std::string& folder,
                                                     const ProgressFn& progress = {});

  // 16 hex digits of the file's text.
  std::string fingerprint(const std::string& path);
  // 16 hex digits of the data loaded from `folder` (its objects, sessions, actions, modalities and
  // values: what decides a campaign's results, not files beside it that the loader skips).
  std::string data_fingerprint(const std::string& folder);

 private:
  std::map<std::string, std::string> texts_;
  std::map<std::string, std::shared_ptr<const pomdp::Problem>> problems_;
  std::map<std::string, std::shared_ptr<const perception::FeatureSet>> data_;
};

}  // namespace echoplan::experiment
