#include "loop/behaviour_costs.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <charconv>
#include <cmath>

#include "common/csv_reader.h"
#include "common/error.h"
#include "common/file_io.h"

namespace echoplan::loop {

namespace {

// The cost `text` spells exactly (no spaces, no '+'), finite and >= 0, or an InputError at the row.
double parse_cost(const std::string& text, const std::string& behaviour, const CsvReader& csv) {
  double value = 0.0;
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, value);
  if (text.empty() || error != std::errc() || stop != end)
    throw InputError(csv.file(), csv.line(),
                     fmt::format("the cost of '{}' is '{}', not a number", behaviour, text));
  if (!std::isfinite(value) || value < 0.0)
    throw InputError(
        csv.file(), csv.line(),
        fmt::format("the cost of '{}' is '{}'; a cost is a finite number >= 0", behaviour, text));
  return value;
}

}  // namespace

std::map<std::string, double> load_behaviour_costs(const std::string& path,
                                                   const std::vector<std::string>& behaviours) {
  CsvReader csv(read_text_file(path, "costs file"), path);
  std::vector<std::string> fields;
  if (!csv.next(fields) || fields != std::vector<std::string>{"behaviour", "cost"})
    throw InputError(path, std::max(csv.line(), 1),
                     "the header must be 'behaviour,cost' (one row per priced behaviour)");
  std::map<std::string, double> costs;
  while (csv.next(fields)) {
    if (fields.size() != 2)
      throw InputError(path, csv.line(),
                       fmt::format("{} cells; a row is 'behaviour,cost'", fields.size()));
    const std::string& behaviour = fields[0];
    if (behaviour.empty()) throw InputError(path, csv.line(), "the behaviour is empty");
    if (std::find(behaviours.begin(), behaviours.end(), behaviour) == behaviours.end())
      throw InputError(path, csv.line(),
                       fmt::format("'{}' is not a behaviour of the data (it has: {})", behaviour,
                                   fmt::join(behaviours, ", ")));
    if (!costs.emplace(behaviour, parse_cost(fields[1], behaviour, csv)).second)
      throw InputError(path, csv.line(), fmt::format("'{}' is priced twice", behaviour));
  }
  return costs;
}

}  // namespace echoplan::loop
