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

// The name of the performance at `file`: its audio file's stem, or (no audio) its first series
// file's name without ".<modality>.csv".
std::string performance_name(const perception::Recording& r, const fs::path& file) {
  if (r.audio) return file.stem().string();
  const std::string name = file.filename().string();
  return name.substr(0, name.size() - ("." + r.series.front().modality + ".csv").size());
}

// Copies the series of `r` (recording_set.h: <name>.<modality>.csv) beside the performance `file`
// of the copy, named after it: noise is heard, not felt, so a sensor's series stay as recorded.
void copy_series(const perception::Recording& r, const fs::path& out, const std::string& file) {
  const fs::path performance(file);
  const std::string name = performance_name(r, performance);
  for (const perception::SeriesFile& s : r.series) {
    const fs::path to = out / performance.parent_path() / (name + "." + s.modality + ".csv");
    fs::create_directories(to.parent_path());
    std::error_code error;
    fs::copy_file(s.path, to, fs::copy_options::overwrite_existing, error);
    if (error) throw InputError(to.string(), 0, "cannot copy the series: " + error.message());
  }
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
    if (!r.audio) {  // nothing to hear: the performance's series as they are
      copy_series(r, out, file);
      row(file, r, session, "", "none");
      if (progress) progress("add noise", static_cast<int>(++done), total);
      continue;
    }
    Rng rng(derive_seed(options.seed, {stable_hash(file)}));
    const audio::AudioClip quiet = audio::read_audio(r.path);
    const sim::BackgroundNoise::Mixed mixed = noise.sources->mix(quiet, noise.ebr_db, rng);
    const std::string noisy = options.keep_quiet ? twin_name(file) : file;
    if (options.keep_quiet) {
      write_clip(out / file, quiet);
      copy_series(r, out, file);
      row(file, r, session, "", "none");
    }
    write_clip(out / noisy, mixed.clip);
    copy_series(r, out, noisy);
    row(noisy, r, session, fmt::format("{}", mixed.ebr_db), mixed.source);
    ++done;
    if (progress) progress("add noise", static_cast<int>(done), total);
  }
  write_file_atomically(out / "manifest.csv", manifest);
  return done;
}

}  // namespace echoplan::loop
