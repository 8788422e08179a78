// A sensor's time series: what one sensor (joint efforts, a wrist force-torque sensor, an
// accelerometer) measured during one performance, channel by channel, with the time of each sample.
//
// On disk (docs/feature-sets.md, "Raw signals"): a CSV file with the header `t,<channel>...` and
// one row per sample, `t` in seconds from the action's start. Samples need not be evenly spaced
// (ROS messages arrive when they arrive); extractors that need a rate resample
// (series_features.h).
#pragma once

#include <string>
#include <vector>

namespace echoplan::signal {

struct Series {
  std::vector<std::string> channels;        // distinct, not empty
  std::vector<double> t;                    // seconds from the action's start, non-decreasing
  std::vector<std::vector<double>> values;  // [channel][sample]: values[c].size() == t.size()

  std::size_t samples() const { return t.size(); }
  // Seconds from the first sample to the last (0 for one sample).
  double duration() const { return t.empty() ? 0.0 : t.back() - t.front(); }
  // Index of channel `name`, or -1.
  int channel_index(const std::string& name) const;
};

// Throws InputError(source, 0, problem) unless `series` keeps the invariants above, has at least
// one channel and one sample, and every time and value is finite.
void check_series(const Series& series, const std::string& source);

// Parses a series file's text. InputError(source, line, problem) for: no header, a header that is
// not `t,<channel>...` with at least one channel, an empty or repeated channel name; a row whose
// cell count differs from the header's; a cell that is not a finite number; a time earlier than
// the row before; no rows.
Series parse_series_csv(const std::string& text, const std::string& source);
// The same, read from `path` (InputError naming it when it cannot be read).
Series read_series_csv(const std::string& path);

// The file's text: header, then one row per sample, every number in the shortest form that reads
// back to the same double.
std::string series_csv(const Series& series);
// Writes series_csv(series) to `path` atomically (common/file_io.h).
void write_series_csv(const std::string& path, const Series& series);

}  // namespace echoplan::signal
