// `echoplan add-noise`: a noisy copy of a recordings tree (loop/noisy_copy.h).
#include <fmt/core.h>
#include <spdlog/spdlog.h>

#include "commands/commands.h"
#include "commands/noise_options.h"
#include "common/error.h"
#include "common/stop_signal.h"
#include "loop/noisy_copy.h"
#include "perception/recording_set.h"

namespace echoplan::cli {
namespace {

struct AddNoiseFlags {
  std::string data;
  NoiseFlags noise;
  std::uint64_t seed = 1;
  bool keep_quiet = false;
  std::string out;
};

void add_noise(const AddNoiseFlags& f) {
  const robot::WorldNoise noise = *world_noise(f.noise);
  const perception::RecordingSet set = perception::load_recording_set(f.data);
  const StopSignal stop;
  const std::size_t done = loop::write_noisy_copy(
      set, noise, f.out, {.seed = f.seed, .keep_quiet = f.keep_quiet},
      [](const std::string&, int written, int total) {
        if (written % 50 == 0 || written == total)
          spdlog::info("{} of {} recordings", written, total);
      },
      stop.flag());
  fmt::print("{} recordings with noise from {} source(s) in {}; manifest: {}/manifest.csv\n", done,
             noise.sources->sources().size(), f.out, f.out);
  if (done < set.recordings.size()) {
    fmt::print(stderr, "echoplan: interrupted; the {} finished recordings are listed\n", done);
    throw Interrupted{};
  }
}

}  // namespace

void add_add_noise_command(CLI::App& app) {
  auto f = std::make_shared<AddNoiseFlags>();
  auto* cmd = app.add_subcommand(
      "add-noise",
      R"(Write a noisy copy of a recordings tree: every recording mixed with background noise at an
event-to-background ratio (EBR: the RMS of the recording's loudest 50 ms over the RMS of the noise
added), one source and ratio per recording drawn from --seed and the recording's path (docs/noise.md).
OUT gets the same files and a manifest.csv with each recording's ebr_db and noise source.
Examples:
  echoplan add-noise --data recordings --noise /usr/share/asterisk/sounds/en_US_f_Allison --ebr 0 -o noisy
  echoplan add-noise --data recordings --noise room white --ebr -6:12 --seed 3 -o noisy)");
  cmd->add_option("--data", f->data, "Recordings tree to copy (DIR/<object>/<action>/*.wav)")
      ->required();
  add_noise_options(*cmd, f->noise, true);
  cmd->add_option("--seed", f->seed, "Seed of every draw")->capture_default_str();
  cmd->add_flag("--keep-quiet", f->keep_quiet,
                "Keep each quiet recording beside its noisy twin (NAME.noisy.wav), both in one "
                "session: a multi-condition training set");
  cmd->add_option("-o,--out", f->out, "Folder to write (created)")->required();
  cmd->callback([f] { add_noise(*f); });
}

}  // namespace echoplan::cli
