// libFuzzer target: arbitrary bytes as a sensor's series file (signal/series.h, `t,<channel>...`),
// then, when it reads, every kind of series features on it. Bad input must end in
// echoplan::InputError; anything else (a crash, a sanitizer report, another exception, a hang) is
// a bug.
#include <cstddef>
#include <cstdint>
#include <string>

#include "common/error.h"
#include "signal/series.h"
#include "signal/series_features.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const echoplan::signal::Series series = echoplan::signal::parse_series_csv(text, "fuzz.csv");
    echoplan::signal::check_series(series, "fuzz.csv");
    for (const char* spec : {"bins(10,mean)", "bins(3,sum)", "stats", "bands(0,1,5,20)",
                             "stats[force_z]", "cy101-haptic"}) {
      try {
        const auto features = echoplan::signal::parse_series_features(spec);
        const auto row = features.extract(series, "fuzz.csv");
        if (features.channels.empty() && row.size() != features.row_length(series.channels.size()))
          __builtin_trap();
      } catch (const echoplan::InputError&) {
      }
    }
  } catch (const echoplan::InputError&) {
  }
  return 0;
}
