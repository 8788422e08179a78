// How a sensor's series (series.h) becomes one feature row: the extractor a modality of raw
// signals declares, by a spec stored in the model file, so training, replay and live compute the
// same features (docs/feature-sets.md, "Raw signals").
//
// Three kinds, as the field computes haptic and vibration features:
//   bins(N,sum|mean[,time-major])
//                      the performance cut into N bins per channel, each bin the sum or the mean of
//                      its samples (CY101's and the UR5 containers' layout: 10 bins per joint);
//                      laid out channel by channel, or with `time-major` bin by bin (every
//                      channel's first bin, then every channel's second, ...), as those datasets
//                      store them
//   stats              per channel: mean, standard deviation, minimum, maximum, RMS
//   bands(E0,E1,...)   per channel: the mean power in each band [E_i, E_i+1) Hz of the series
//                      (vibration), after resampling it onto an even grid at its median rate
// Any kind may name the channels it reads, in order: `bins(10,mean)[force_x,force_y,force_z]`;
// without a list it reads every channel in the series' order. Presets name common layouts
// (series_feature_presets()).
//
// A spec is parsed and checked once (parse_series_features); extract() then only computes.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "signal/series.h"

namespace echoplan::signal {

struct SeriesFeatures {
  enum class Kind { bins, stats, bands };
  enum class Reduce { sum, mean };

  Kind kind = Kind::bins;
  int bins = 10;                      // bins: how many, 1..1000
  Reduce reduce = Reduce::mean;       // bins: a bin's value
  bool time_major = false;            // bins: the row bin by bin rather than channel by channel
  std::vector<double> band_edges;     // bands: Hz, >= 0, strictly increasing, at least two
  std::vector<std::string> channels;  // read in this order; empty: every channel, series order

  // The canonical spec text (parse_series_features(spec()) gives this extractor back).
  std::string spec() const;
  // The row's length for a series of `series_channels` channels (when `channels` is empty).
  std::size_t row_length(std::size_t series_channels) const;
  // The features' names: <channel>_b<k> (k from 1), <channel>_<stat>, <channel>_<lo>_<hi>hz.
  std::vector<std::string> feature_names(const std::vector<std::string>& series_channels) const;
  // The row of `series`. InputError(source, 0, ...) for a channel it names that the series lacks,
  // fewer samples than bins (bins), or fewer than 4 samples or a band above half the rate (bands).
  std::vector<double> extract(const Series& series, const std::string& source) const;
};

// A spec (above) or a preset's name. InputError naming the spec and what is wrong with it, with
// the kinds and presets listed for an unknown one.
SeriesFeatures parse_series_features(std::string_view spec);

// The presets: name and spec.
struct SeriesFeaturePreset {
  const char* name;
  const char* spec;
  const char* what;  // one line for --help and the docs
};
const std::vector<SeriesFeaturePreset>& series_feature_presets();

// The default for a modality nobody chose an extractor for: bins(10,mean), since means do not
// change with the length of a performance or the sensor's rate (sums do).
inline constexpr const char* kDefaultSeriesFeatures = "bins(10,mean)";

}  // namespace echoplan::signal
