#include "commands/noise_options.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "common/error.h"

namespace echoplan::cli {

void add_noise_options(CLI::App& cmd, NoiseFlags& flags, bool required) {
  auto* noise = cmd.add_option(
      "--noise", flags.sources,
      fmt::format("Background noise sources: recordings, folders of them (read recursively), or "
                  "built-in {} (room: flat below 500 Hz, -6 dB per octave above; motor: the "
                  "simulated arm's motor band). Real speech: "
                  "/usr/share/asterisk/sounds/en_US_f_Allison (docs/noise.md)",
                  fmt::join(sim::builtin_noise_names(), ", ")));
  auto* ebr = cmd.add_option("--ebr", flags.ebr,
                             "Event-to-background ratio in dB, X or a range LO:HI drawn per "
                             "recording, in [-60, 60]");
  cmd.add_option("--talkers", flags.talkers,
                 fmt::format("Babble: how many segments of the recorded sources are heard at once "
                             "(1 to {}; one talker leaves gaps, many fill them)",
                             sim::BackgroundNoise::kMostTalkers))
      ->default_val(1);
  if (required) {
    noise->required();
    ebr->required();
  }
}

std::optional<robot::WorldNoise> world_noise(const NoiseFlags& flags) {
  if (flags.sources.empty() && flags.talkers != 1)
    throw InputError("--talkers needs --noise: the recordings the talkers are drawn from");
  if (flags.sources.empty() && flags.ebr.empty()) return std::nullopt;
  if (flags.sources.empty()) throw InputError("--ebr needs --noise: the sources to mix in");
  if (flags.ebr.empty()) throw InputError("--noise needs --ebr: the ratio to mix them at");
  const sim::EbrRange ebr = sim::parse_ebr(flags.ebr);
  return robot::WorldNoise{
      std::make_shared<const sim::BackgroundNoise>(flags.sources, flags.talkers), ebr};
}

}  // namespace echoplan::cli
