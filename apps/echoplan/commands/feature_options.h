// Options shared by `echoplan features` and `echoplan heatmap`: which preset, which feature, how to
// read the channels, and the reading itself.
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "audio/clip.h"

namespace echoplan::cli {

struct FeatureOptions {
  std::string preset = "psf";
  std::string feature;           // empty: summary (features) or logmel (heatmap)
  std::string channel = "mean";  // "mean" or a 0-based channel index
  int resample_hz = 0;           // 0: the file's own rate
  std::string format = "csv";
  std::string output;
  std::vector<std::string> files;
};

// Adds --preset, --feature, --channel and --resample to `cmd`, bound to `options`.
void add_feature_options(CLI::App& cmd, FeatureOptions& options);

// Reads `path` as one channel (mean or the chosen one) at the chosen rate; InputError on any
// problem.
audio::AudioClip read_for_features(const FeatureOptions& options, const std::string& path);

}  // namespace echoplan::cli
