// `echoplan add-noise`: a noisy copy of a recordings tree, each recording mixed with background
// noise at an event-to-background ratio (sim/background_noise.h), and a manifest that says which
// source and ratio each got. A recording's noise comes from the seed and the recording's path
// alone, so a rerun (after an interruption, or on another machine) writes the same files.
#include <fmt/core.h>
#include <spdlog/spdlog.h>

#include <filesystem>
#include <sstream>

#include "audio/io.h"
#include "commands/commands.h"
#include "common/error.h"
#include "common/file_io.h"
#include "common/rng.h"
#include "common/stable_hash.h"
#include "common/stop_signal.h"
#include "perception/recording_set.h"
#include "sim/background_noise.h"

namespace echoplan::cli {
namespace {

namespace fs = std::filesystem;

struct AddNoiseFlags {
  std::string data;
  std::vector<std::string> noise;
  std::string ebr;
  std::uint64_t seed = 1;
  std::string out;
};

// One manifest row: the recording's labels, then the ratio and the source.
std::string manifest_row(const std::string& file, const perception::Recording& r, bool sessions,
                         const sim::BackgroundNoise::Mixed& mixed) {
  return fmt::format("{},{},{}{},{},{}\n", file, r.object, r.action,
                     sessions ? "," + r.session : "", mixed.ebr_db, mixed.source);
}

void add_noise(const AddNoiseFlags& f) {
  const sim::EbrRange ebr = sim::parse_ebr(f.ebr);
  const perception::RecordingSet set = perception::load_recording_set(f.data);
  std::error_code error;
  if (fs::exists(f.out, error) && fs::equivalent(f.out, f.data, error))
    throw InputError(f.out, 0, "the noisy copy must go to another folder than --data");
  const sim::BackgroundNoise noise(f.noise);
  bool sessions = false;
  for (const perception::Recording& r : set.recordings) sessions = sessions || !r.session.empty();
  std::string manifest =
      sessions ? "file,object,action,session,ebr_db,noise\n" : "file,object,action,ebr_db,noise\n";
  const StopSignal stop;
  std::size_t done = 0;
  for (const perception::Recording& r : set.recordings) {
    if (stop.flag().load()) break;
    const std::string file = fs::path(r.path).lexically_relative(set.root).generic_string();
    Rng rng(derive_seed(f.seed, {stable_hash(file)}));
    const sim::BackgroundNoise::Mixed mixed = noise.mix(audio::read_audio(r.path), ebr, rng);
    const fs::path written = fs::path(f.out) / file;
    fs::create_directories(written.parent_path());
    audio::write_audio(written.string(), mixed.clip, audio::write_options_for(written.string()));
    manifest += manifest_row(file, r, sessions, mixed);
    if (++done % 50 == 0 || done == set.recordings.size())
      spdlog::info("{} of {} recordings", done, set.recordings.size());
  }
  // The manifest lists what is written, so an interrupted copy is a recordings tree too.
  write_file_atomically(fs::path(f.out) / "manifest.csv", manifest);
  fmt::print("{} recordings with noise from {} source(s) in {}; manifest: {}/manifest.csv\n", done,
             noise.sources().size(), f.out, f.out);
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
  cmd->add_option("--noise", f->noise,
                  "Noise sources: recordings, folders of them (read recursively), or built-in "
                  "'white' and 'room' (room-shaped: flat below 500 Hz, -6 dB per octave above)")
      ->required();
  cmd->add_option("--ebr", f->ebr,
                  "EBR in dB, X or a range LO:HI drawn per recording, in [-60, 60]")
      ->required();
  cmd->add_option("--seed", f->seed, "Seed of every draw")->capture_default_str();
  cmd->add_option("-o,--out", f->out, "Folder to write (created)")->required();
  cmd->callback([f] { add_noise(*f); });
}

}  // namespace echoplan::cli
