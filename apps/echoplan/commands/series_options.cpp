#include "commands/series_options.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "common/error.h"
#include "signal/series_features.h"

namespace echoplan::cli {

void add_series_option(CLI::App& cmd, std::vector<std::string>& typed) {
  std::vector<std::string> presets;
  for (const auto& p : signal::series_feature_presets())
    presets.push_back(fmt::format("{} = {}", p.name, p.spec));
  cmd.add_option(
      "--series", typed,
      fmt::format("How a recordings tree's series <name>.<modality>.csv become rows, "
                  "as MODALITY=FEATURES (repeatable): bins(N,sum|mean[,time-major]), stats or "
                  "bands(E0,E1,...) in Hz, optionally followed by [channel,...], or a "
                  "preset ({}). Default for every series: {}",
                  fmt::join(presets, "; "), signal::kDefaultSeriesFeatures));
}

perception::SeriesChoices parse_series_choices(const std::vector<std::string>& typed) {
  perception::SeriesChoices choices;
  for (const std::string& text : typed) {
    const auto equals = text.find('=');
    if (equals == std::string::npos || equals == 0)
      throw InputError(fmt::format(
          "--series '{}': expected MODALITY=FEATURES, e.g. effort=bins(10,mean)", text));
    const std::string modality = text.substr(0, equals);
    try {
      const std::string spec = signal::parse_series_features(text.substr(equals + 1)).spec();
      if (!choices.emplace(modality, spec).second)
        throw InputError(fmt::format("'{}' is named twice", modality));
    } catch (const InputError& error) {
      throw InputError(fmt::format("--series {}: {}", text, error.problem()));
    }
  }
  return choices;
}

}  // namespace echoplan::cli
