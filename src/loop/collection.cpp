#include "loop/collection.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <optional>
#include <set>
#include <utility>

#include "audio/io.h"
#include "common/csv_reader.h"
#include "common/error.h"
#include "common/file_io.h"
#include "common/rng.h"
#include "common/stable_hash.h"
#include "robot/transient_error.h"

namespace echoplan::loop {

namespace {

namespace fs = std::filesystem;
using NamedSeries = std::vector<std::pair<std::string, signal::Series>>;

constexpr const char* kHeader = "file,object,action,session,status";

void check_plan(const CollectionPlan& plan) {
  auto distinct = [](const std::vector<std::string>& names, const char* what) {
    if (names.empty()) throw InputError("", 0, fmt::format("no {} to collect", what));
    std::set<std::string> seen;
    for (const auto& n : names)
      if (n.empty() || !seen.insert(n).second)
        throw InputError("", 0, fmt::format("{} '{}' is empty or named twice", what, n));
  };
  distinct(plan.objects, "objects");
  distinct(plan.behaviours, "behaviours");
  if (plan.sessions < 1) throw InputError("", 0, "--sessions must be at least 1");
}

// The (object, session, behaviour) performances an earlier run of this collection finished: the
// rows of DIR/manifest.csv, which must be this collection's.
std::set<std::string> finished(const fs::path& manifest) {
  std::set<std::string> done;
  if (!fs::exists(manifest)) return done;
  CsvReader csv(read_text_file(manifest.string(), "the manifest"), manifest.string());
  std::vector<std::string> fields;
  if (!csv.next(fields) || fmt::format("{}", fmt::join(fields, ",")) != kHeader)
    throw InputError(manifest.string(), 1,
                     fmt::format("not a collection's manifest (its header must be {}): choose "
                                 "another folder",
                                 kHeader));
  while (csv.next(fields)) {
    if (fields.size() != 5)
      throw InputError(manifest.string(), csv.line(),
                       fmt::format("{} fields, expected 5 ({})", fields.size(), kHeader));
    done.insert(fields[1] + '\n' + fields[3] + '\n' + fields[2]);
  }
  return done;
}

// The manifest, opened to append (with its header when new).
std::ofstream open_manifest(const fs::path& path) {
  const bool fresh = !fs::exists(path);
  std::ofstream out(path, std::ios::app);
  if (fresh) out << kHeader << '\n';
  if (!out.flush()) throw InputError(path.string(), 0, "cannot write the manifest");
  return out;
}

// What one performance gave: its clip (when a recorder listened) and its signals.
struct Performance {
  std::optional<audio::AudioClip> clip;
  NamedSeries series;
};

// Writes one performance's files and returns the manifest's name for it: its WAV, or without one
// its first series.
std::string write_performance(const fs::path& root, const std::string& object,
                              const std::string& behaviour, int session, const Performance& p) {
  const fs::path folder = root / object / behaviour;
  std::error_code ec;
  fs::create_directories(folder, ec);
  if (ec) throw InputError(folder.string(), 0, "cannot create the folder: " + ec.message());
  const std::string stem = fmt::format("{}/{}/s{:03d}", object, behaviour, session);
  for (const auto& [modality, s] : p.series)
    signal::write_series_csv((root / fmt::format("{}.{}.csv", stem, modality)).string(), s);
  if (!p.clip) return fmt::format("{}.{}.csv", stem, p.series.front().first);
  const fs::path wav = root / (stem + ".wav");
  const fs::path partial = wav.string() + ".part";
  audio::write_audio(partial.string(), *p.clip, audio::WriteOptions{});
  move_into_place(partial, wav);
  return stem + ".wav";
}

// Performs `behaviour` with the recorder (if any) around it and gathers its signals. A
// TransientError of the recorder or the signals propagates: the performance is lost.
std::pair<robot::ActionReport, Performance> perform(robot::Robot& robot, robot::Recorder* recorder,
                                                    const PerformanceSignals& signals,
                                                    const std::string& object, int session,
                                                    const std::string& behaviour) {
  Performance p;
  if (recorder) recorder->start(behaviour);
  robot::ActionReport report = robot.execute(behaviour);
  if (recorder) p.clip = recorder->stop();
  if (signals) p.series = signals(object, session, behaviour);
  if (!recorder && p.series.empty())
    throw InputError(fmt::format(
        "{} session {} {}: no microphone and no signal: a performance must record something",
        object, session, behaviour));
  return {std::move(report), std::move(p)};
}

}  // namespace

CollectionSummary collect(robot::Robot& robot, robot::Recorder* recorder,
                          const CollectionPlan& plan, const PerformanceSignals& signals,
                          const CollectionProgress& progress, const std::atomic<bool>& stop) {
  check_plan(plan);
  const fs::path root(plan.output_dir);
  std::error_code ec;
  fs::create_directories(root, ec);
  if (ec) throw InputError(plan.output_dir, 0, "cannot create the folder: " + ec.message());
  const std::set<std::string> done = finished(root / "manifest.csv");
  std::ofstream manifest = open_manifest(root / "manifest.csv");
  CollectionSummary summary;
  const int total = static_cast<int>(plan.objects.size() * plan.behaviours.size()) * plan.sessions;
  int trial = 0;
  for (const std::string& object : plan.objects)
    for (int session = 1; session <= plan.sessions; ++session) {
      bool begun = false;
      for (const std::string& behaviour : plan.behaviours) {
        if (done.count(object + '\n' + std::to_string(session) + '\n' + behaviour)) {
          ++summary.kept;
          continue;
        }
        if (stop) {
          summary.interrupted = true;
          return summary;
        }
        if (!begun) {
          const robot::TrialContext context{
              ++trial, object,
              derive_seed(plan.seed, {stable_hash(object), static_cast<std::uint64_t>(session)})};
          robot.begin_trial(context);
          if (recorder) recorder->begin_trial(context);
          begun = true;
        }
        CollectionStep step{object, session, behaviour, 0, total, ""};
        try {
          const auto [report, performance] =
              perform(robot, recorder, signals, object, session, behaviour);
          const std::string file = write_performance(root, object, behaviour, session, performance);
          manifest << fmt::format("{},{},{},{},{}\n", file, object, behaviour, session,
                                  to_string(report.status))
                   << std::flush;
          if (!manifest) throw InputError((root / "manifest.csv").string(), 0, "cannot write it");
          ++summary.performed;
          if (report.status != robot::ActionStatus::done) ++summary.failed;
        } catch (const robot::TransientError& e) {
          ++summary.lost;
          step.lost = e.what();
        }
        step.done = summary.performed + summary.kept;
        if (progress) progress(step);
      }
    }
  return summary;
}

}  // namespace echoplan::loop
