// The --series option: how a recordings tree's series files become rows, per modality
// (signal/series_features.h), shared by the commands that compute features from a tree.
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "perception/recording_features.h"

namespace echoplan::cli {

// Adds --series MODALITY=FEATURES (repeatable) to `cmd`, bound to `typed`.
void add_series_option(CLI::App& cmd, std::vector<std::string>& typed);

// The choices typed as MODALITY=FEATURES, each spec checked. InputError naming the flag for a
// missing '=', an empty modality, a modality named twice or a bad spec.
perception::SeriesChoices parse_series_choices(const std::vector<std::string>& typed);

}  // namespace echoplan::cli
