#include "loop/noisy_copy.h"

#include <fmt/format.h>

#include "audio/io.h"
#include "common/error.h"
#include "common/file_io.h"
#include "common/rng.h"
#include "common/stable_hash.h"

namespace echoplan::loop {

namespace fs = std::filesystem;

namespace {

// `file` with ".noisy" before its extension.
std::string twin_name(const std::string& file) {
  const fs::path path(file);
  return (path.parent_path() / (path.stem().string() + ".noisy" + path.extension().string()))
      .generic_string();
}

void write_clip(const fs::path& path, const audio::AudioClip& clip) {
  fs::create_directories(path.parent_path());
  audio::write_audio(path.string(), clip, audio::write_options_for(path.string()));
}

}  // namespace

std::size_t write_noisy_copy(const perception::RecordingSet& set, const robot::WorldNoise& noise,
                             const fs::path& out, const NoisyCopyOptions& options,
                             const ProgressFn& progress, const std::atomic<bool>& stop) {
  std::error_code error;
  if (fs::exists(out, error) && fs::equivalent(out, set.root, error))
    throw InputError(out.string(), 0, "the noisy copy must go to another folder than the data");
  bool sessions = options.keep_quiet;
  for (const perception::Recording& r : set.recordings) sessions = sessions || !r.session.empty();
  std::string manifest =
      sessions ? "file,object,action,session,ebr_db,noise\n" : "file,object,action,ebr_db,noise\n";
  const auto row = [&](const std::string& file, const perception::Recording& r,
                       const std::string& session, const std::string& ebr,
                       const std::string& source) {
    manifest += fmt::format("{},{},{}{},{},{}\n", file, r.object, r.action,
                            sessions ? "," + session : "", ebr, source);
  };
  const int total = static_cast<int>(set.recordings.size());
  std::size_t done = 0;
  for (const perception::Recording& r : set.recordings) {
    if (stop.load()) break;
    const std::string file = fs::path(r.path).lexically_relative(set.root).generic_string();
    const std::string session = r.session.empty() ? file : r.session;
    Rng rng(derive_seed(options.seed, {stable_hash(file)}));
    const audio::AudioClip quiet = audio::read_audio(r.path);
    const sim::BackgroundNoise::Mixed mixed = noise.sources->mix(quiet, noise.ebr_db, rng);
    const std::string noisy = options.keep_quiet ? twin_name(file) : file;
    if (options.keep_quiet) {
      write_clip(out / file, quiet);
      row(file, r, session, "", "none");
    }
    write_clip(out / noisy, mixed.clip);
    row(noisy, r, session, fmt::format("{}", mixed.ebr_db), mixed.source);
    ++done;
    if (progress) progress("add noise", static_cast<int>(done), total);
  }
  write_file_atomically(out / "manifest.csv", manifest);
  return done;
}

}  // namespace echoplan::loop
