// A campaign's input files and folders, each read once: a problem is parsed from the same text its
// fingerprint in the campaign's identity is taken from, and a dataset world's data is loaded once
// and fingerprinted as loaded. A recordings tree's analysed audio is read back from a campaign
// folder that kept it (analysed_recordings.h) instead of analysed again.
#pragma once

#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "common/progress.h"
#include "perception/feature_set.h"
#include "perception/recording_features.h"
#include "pomdp/problem.h"

namespace echoplan::experiment {

class InputFiles {
 public:
  // `campaign_folders`: where a recordings tree's analysed audio may be kept; the first is where
  // keep_analysed() writes it (a campaign's folder, then for a merge its shards'). `series`: how a
  // recordings tree's series become rows (the campaign's world.series).
  explicit InputFiles(std::vector<std::filesystem::path> campaign_folders = {},
                      perception::SeriesChoices series = {});

  // The file's text (InputError naming it when it cannot be read).
  const std::string& text(const std::string& path);
  // The problem in the file, parsed once.
  std::shared_ptr<const pomdp::Problem> problem(const std::string& path);
  // The data in `folder` (a feature set or a recordings tree: perception::load_data), loaded once;
  // a recordings tree from a campaign folder's kept analysis when it is still the tree's.
  std::shared_ptr<const perception::FeatureSet> data(const std::string& folder,
                                                     const ProgressFn& progress = {});

  // 16 hex digits of the file's text.
  std::string fingerprint(const std::string& path);
  // 16 hex digits of the data loaded from `folder` (its objects, sessions, actions, modalities and
  // values: what decides a campaign's results, not files beside it that the loader skips).
  std::string data_fingerprint(const std::string& folder);

  // Writes, in the first campaign folder, the analysis of the recordings tree this analysed (none
  // when it read it back, or loaded no recordings tree). Called once the folder is the campaign's.
  void keep_analysed() const;

 private:
  // A recordings tree analysed here, to be kept.
  struct Analysed {
    std::string folder;
    std::string listing;
    std::shared_ptr<const perception::FeatureSet> data;
  };
  std::shared_ptr<const perception::FeatureSet> load(const std::string& folder,
                                                     const ProgressFn& progress);

  std::vector<std::filesystem::path> campaign_folders_;
  perception::SeriesChoices series_;
  std::optional<Analysed> analysed_;
  std::map<std::string, std::string> texts_;
  std::map<std::string, std::shared_ptr<const pomdp::Problem>> problems_;
  std::map<std::string, std::shared_ptr<const perception::FeatureSet>> data_;
};

}  // namespace echoplan::experiment
