#include "signal/series.h"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <set>

#include "common/csv_reader.h"
#include "common/error.h"
#include "common/file_io.h"

namespace echoplan::signal {

int Series::channel_index(const std::string& name) const {
  for (std::size_t c = 0; c < channels.size(); ++c)
    if (channels[c] == name) return static_cast<int>(c);
  return -1;
}

void check_series(const Series& series, const std::string& source) {
  if (series.channels.empty()) throw InputError(source, 0, "the series has no channel");
  if (series.t.empty()) throw InputError(source, 0, "the series has no sample");
  if (series.values.size() != series.channels.size())
    throw InputError(source, 0,
                     fmt::format("{} channels named but {} given", series.channels.size(),
                                 series.values.size()));
  std::set<std::string> seen;
  for (std::size_t c = 0; c < series.channels.size(); ++c) {
    const std::string& name = series.channels[c];
    if (name.empty()) throw InputError(source, 0, fmt::format("channel {} has no name", c + 1));
    if (!seen.insert(name).second)
      throw InputError(source, 0, fmt::format("channel '{}' appears twice", name));
    if (series.values[c].size() != series.t.size())
      throw InputError(source, 0,
                       fmt::format("channel '{}' has {} samples where the times have {}", name,
                                   series.values[c].size(), series.t.size()));
    for (double v : series.values[c])
      if (!std::isfinite(v))
        throw InputError(source, 0, fmt::format("channel '{}' has a value {}", name, v));
  }
  for (std::size_t i = 0; i < series.t.size(); ++i) {
    if (!std::isfinite(series.t[i]))
      throw InputError(source, 0, fmt::format("sample {} has the time {}", i + 1, series.t[i]));
    if (i > 0 && series.t[i] < series.t[i - 1])
      throw InputError(source, 0,
                       fmt::format("sample {} at {} s comes before sample {} at {} s", i + 1,
                                   series.t[i], i, series.t[i - 1]));
  }
}

namespace {

void check_header(const std::vector<std::string>& header, const std::string& source) {
  if (header.size() < 2 || header[0] != "t")
    throw InputError(source, 1, "the header must be t followed by at least one channel name");
  std::set<std::string> seen;
  for (std::size_t c = 1; c < header.size(); ++c) {
    if (header[c].empty())
      throw InputError(source, 1, fmt::format("channel name {} (column {}) is empty", c, c + 1));
    if (!seen.insert(header[c]).second)
      throw InputError(source, 1, fmt::format("channel '{}' appears twice", header[c]));
  }
}

// The finite number `text` spells exactly (no spaces, no leading '+'), or an InputError.
double parse_cell(const std::string& text, const std::string& column, const CsvReader& csv) {
  double value = 0.0;
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, value);
  if (text.empty() || error != std::errc() || stop != end)
    throw InputError(csv.file(), csv.line(),
                     fmt::format("'{}' is '{}', not a number", column, text));
  if (!std::isfinite(value))
    throw InputError(csv.file(), csv.line(),
                     fmt::format("'{}' is '{}': values must be finite", column, text));
  return value;
}

}  // namespace

Series parse_series_csv(const std::string& text, const std::string& source) {
  CsvReader csv(text, source);
  std::vector<std::string> header, cells;
  if (!csv.next(header) || csv.line() != 1)
    throw InputError(source, 1, "no header: expected t,<channel>,...");
  check_header(header, source);
  Series series;
  series.channels.assign(header.begin() + 1, header.end());
  series.values.resize(series.channels.size());
  while (csv.next(cells)) {
    if (cells.size() != header.size())
      throw InputError(source, csv.line(),
                       fmt::format("{} cells, but the header has {} columns (a ragged row)",
                                   cells.size(), header.size()));
    const double t = parse_cell(cells[0], "t", csv);
    if (!series.t.empty() && t < series.t.back())
      throw InputError(source, csv.line(),
                       fmt::format("time {} s is earlier than the row before ({} s): rows must be "
                                   "in time order",
                                   t, series.t.back()));
    series.t.push_back(t);
    for (std::size_t c = 1; c < cells.size(); ++c)
      series.values[c - 1].push_back(parse_cell(cells[c], header[c], csv));
  }
  if (series.t.empty()) throw InputError(source, 2, "no samples after the header");
  return series;
}

Series read_series_csv(const std::string& path) {
  return parse_series_csv(read_text_file(path, "series file"), path);
}

std::string series_csv(const Series& series) {
  std::string out = "t";
  for (const std::string& channel : series.channels) out += "," + channel;
  out += '\n';
  for (std::size_t i = 0; i < series.t.size(); ++i) {
    fmt::format_to(std::back_inserter(out), "{}", series.t[i]);
    for (const auto& channel : series.values)
      fmt::format_to(std::back_inserter(out), ",{}", channel[i]);
    out += '\n';
  }
  return out;
}

void write_series_csv(const std::string& path, const Series& series) {
  write_file_atomically(path, series_csv(series));
}

}  // namespace echoplan::signal
