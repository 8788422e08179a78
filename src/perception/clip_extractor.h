// Clip extractors: how an analysed clip becomes one feature row, by name. Audio is one modality
// among others: once a clip is a row, every row classifier (row_classifier.h) and the one
// observation model treat it as they treat a force or effort sensor's rows.
//   summary         the 123 level-normalised summary features (summary_features.h)
//   onset-logfbank  the onset-aligned log-filterbank window of the report's templates
//   centroid-rms    (spectral centroid in Hz, RMS) of the whole clip
//   spectrogram-grid  CY101's 10 x 10 grid of mean log powers (spectrogram_grid.h)
//   pcen-summary    the mel spectrum after per-channel energy normalisation (pcen_summary.h)
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "perception/clip_analysis.h"

namespace echoplan::perception {

struct ClipExtractor {
  std::string name;
  std::vector<double> (*extract)(const ClipAnalysis& clip);
  // The features' names, one per entry of a row; empty where a row's length follows the clip
  // analysis (onset-logfbank's bands).
  std::vector<std::string> (*feature_names)();
};

// Every registered name.
std::vector<std::string> clip_extractor_names();
// The extractor called `name`; InputError listing the names for an unknown one.
const ClipExtractor& clip_extractor(std::string_view name);

}  // namespace echoplan::perception
