#include "sim/simulated_recordings.h"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <memory>
#include <mutex>
#include <optional>

#include "audio/io.h"
#include "common/error.h"
#include "common/file_io.h"
#include "common/parallel_jobs.h"
#include "common/rng.h"
#include "common/stable_hash.h"
#include "signal/series.h"
#include "sim/arm_sensors.h"
#include "sim/recording.h"
#include "sim/simulated_robot.h"
#include "sim/sound_action.h"
#include "sim/table_choice.h"

namespace echoplan::sim {

std::uint64_t clip_seed(std::uint64_t seed, const std::string& object, const std::string& action,
                        int index) {
  return derive_seed(seed,
                     {stable_hash(object), stable_hash(action), static_cast<std::uint64_t>(index)});
}

const std::vector<std::string>& simulated_signals() {
  static const std::vector<std::string> names{"audio", "effort", "force"};
  return names;
}

namespace {

// `signals` checked: known names, each once, at least one.
void check_signals(const std::vector<std::string>& signals) {
  if (signals.empty())
    throw InputError("", 0, "no signals to record: name at least one of audio, effort, force");
  const auto& known = simulated_signals();
  for (std::size_t i = 0; i < signals.size(); ++i) {
    if (std::find(known.begin(), known.end(), signals[i]) == known.end())
      throw InputError(
          "", 0, fmt::format("unknown signal '{}' (known: audio, effort, force)", signals[i]));
    if (std::find(signals.begin(), signals.begin() + static_cast<long>(i), signals[i]) !=
        signals.begin() + static_cast<long>(i))
      throw InputError("", 0, fmt::format("signal '{}' named twice", signals[i]));
  }
}

bool records(const std::vector<std::string>& signals, const std::string& name) {
  return std::find(signals.begin(), signals.end(), name) != signals.end();
}

// Writes clip `index`'s files (audio and the sensors' series, as `signals` asks) into
// root/<object>/<action>/ and returns the manifest's name for it: its WAV, else its first series
// in the order `signals` names them.
std::string write_clip_files(const std::filesystem::path& root, const std::string& stem,
                             Recording& r, const std::vector<std::string>& signals,
                             const SensorConfig& sensors, std::uint64_t seed) {
  std::string listed;
  if (records(signals, "audio")) {
    listed = stem + ".wav";
    const std::filesystem::path partial = (root / listed).string() + ".part";
    audio::write_audio(partial.string(), r.clip, audio::WriteOptions{});
    move_into_place(partial, root / listed);
  }
  Rng noise(derive_seed(seed, {stable_hash("arm sensors")}));
  add_sensor_noise(r.outcome.readings, sensors, noise);
  for (const std::string& name : signals) {
    if (name == "audio") continue;
    const std::string relative = fmt::format("{}.{}.csv", stem, name);
    signal::write_series_csv((root / relative).string(), name == "effort"
                                                             ? r.outcome.readings.effort
                                                             : r.outcome.readings.force);
    if (listed.empty()) listed = relative;
  }
  return listed;
}

// One clip to record.
struct Job {
  std::string object;
  SoundAction action;
  int index;
};

// The clips in manifest order, each (object, action) folder created.
std::vector<Job> list_jobs(const std::filesystem::path& root,
                           const std::vector<std::string>& objects,
                           const std::vector<SoundAction>& actions, int per_pair) {
  std::vector<Job> jobs;
  std::error_code ec;
  for (const auto& object : objects)
    for (const SoundAction action : actions) {
      const std::filesystem::path folder = root / object / to_string(action);
      std::filesystem::create_directories(folder, ec);
      if (ec) throw InputError(folder.string(), 0, "cannot create the folder: " + ec.message());
      for (int i = 0; i < per_pair; ++i) jobs.push_back({object, action, i});
    }
  return jobs;
}

// The manifest at `path`, truncated, with its header row written; a `surface` column when the
// config names tables (sets recorded on the default table keep their manifest as it was).
std::ofstream open_manifest(const std::filesystem::path& path, bool surfaces) {
  std::ofstream manifest(path, std::ios::trunc);
  if (!manifest) throw InputError(path.string(), 0, "cannot write the manifest");
  manifest << "file,object,action,seed,collision,duration_s,impacts";
  for (const auto& [name, value] : ActionVariation{}.named()) manifest << ',' << name;
  for (const auto& [name, value] : ObjectPlacement{}.named()) manifest << ',' << name;
  // Last, so readers of the columns before it find them where they were: recording i of every
  // action of an object is its exploration (session) i + 1, so the set is a dataset world's data
  // as it stands (docs/feature-sets.md).
  manifest << ",session";
  if (surfaces) manifest << ",surface";
  manifest << '\n' << std::flush;
  return manifest;
}

// One clip's manifest row (without its newline).
std::string manifest_row(const std::string& relative, const std::string& object,
                         const std::string& action, int index, std::uint64_t seed,
                         const ActionOutcome& outcome) {
  std::string row =
      fmt::format("{},{},{},{},{},{:.4f},{}", relative, object, action, seed,
                  outcome.collision() ? 1 : 0, outcome.duration_s, outcome.trace.impacts.size());
  for (const auto& [name, value] : outcome.variation.named()) row += fmt::format(",{:.6g}", value);
  for (const auto& [name, value] : outcome.placement.named()) row += fmt::format(",{:.6g}", value);
  row += fmt::format(",{}", index + 1);
  return row;
}

}  // namespace

SimulatedRecordingsSummary write_simulated_recordings(const Catalogue& catalogue,
                                                      const SimConfig& config,
                                                      const SimulatedRecordingsOptions& options,
                                                      const ProgressFn& progress,
                                                      const std::atomic<bool>& stop) {
  namespace fs = std::filesystem;
  const std::vector<std::string> objects =
      options.objects.empty() ? catalogue.object_names() : options.objects;
  for (const auto& o : objects) catalogue.object(o);  // throws for an unknown name, before any file
  std::vector<SoundAction> actions;                   // throws for an unknown name, before any file
  for (const auto& a : options.actions) actions.push_back(parse_sound_action(a));
  if (options.per_pair < 1) throw InputError("", 0, "--per-pair must be at least 1");
  check_signals(options.signals);

  const fs::path root(options.output_dir);
  std::error_code ec;
  fs::create_directories(root, ec);
  if (ec)
    throw InputError(options.output_dir, 0, "cannot create the output folder: " + ec.message());
  const fs::path manifest_path = root / "manifest.csv";
  check_tables(catalogue, config);  // before any file
  std::ofstream manifest = open_manifest(manifest_path, !config.tables.empty());

  // The clips in manifest order. Workers take the next clip in turn; each keeps one robot and
  // renderer for the object it is on (compiling the MuJoCo scene is the expensive part). Every clip
  // has its own seed, so which worker renders it does not change its bytes; rows are written in
  // manifest order as soon as all earlier clips are done.
  const std::vector<Job> jobs = list_jobs(root, objects, actions, options.per_pair);
  const int total = static_cast<int>(jobs.size());
  struct Done {
    std::string file, row;
    bool collision = false;
  };
  std::vector<std::optional<Done>> done(jobs.size());
  std::size_t next_row = 0;
  std::mutex mutex;
  SimulatedRecordingsSummary summary;
  auto write_row = [&](const Done& d) {
    manifest << d.row << '\n' << std::flush;
    if (!manifest) throw InputError(manifest_path.string(), 0, "cannot write the manifest");
    ++summary.written;
    if (d.collision) ++summary.collisions;
  };
  // What a thread keeps between its clips: the robot and renderer of the object and table it is
  // on.
  struct CurrentObject {
    std::string object, table;
    std::unique_ptr<SimulatedRobot> robot;
    std::unique_ptr<SoundRenderer> renderer;
  };
  run_jobs(
      jobs.size(), options.threads,
      [&]() -> JobRunner {
        auto scene = std::make_shared<CurrentObject>();
        return [&, scene](std::size_t k) {
          const Job& job = jobs[k];
          const TableSpec& table = table_of_recording(catalogue, config, job.index);
          if (job.object != scene->object || table.name != scene->table) {
            scene->robot = std::make_unique<SimulatedRobot>(catalogue, job.object, config, table);
            scene->renderer = std::make_unique<SoundRenderer>(scene->robot->object(),
                                                              scene->robot->table(), config);
            scene->object = job.object;
            scene->table = table.name;
          }
          const std::string action = to_string(job.action);
          const std::uint64_t seed = clip_seed(options.seed, job.object, action, job.index);
          Rng rng(seed);
          Recording r = simulate_recording(*scene->robot, *scene->renderer, job.action, rng);
          const std::string relative =
              write_clip_files(root, fmt::format("{}/{}/{:03d}", job.object, action, job.index), r,
                               options.signals, config.sensors, seed);
          std::string row = manifest_row(relative, job.object, action, job.index, seed, r.outcome);
          if (!config.tables.empty()) row += "," + table.name;
          std::lock_guard lock(mutex);
          done[k] = Done{relative, std::move(row), r.outcome.collision()};
          for (; next_row < done.size() && done[next_row]; ++next_row) {
            write_row(*done[next_row]);
            if (progress) progress(done[next_row]->file, summary.written, total);
          }
          return true;
        };
      },
      &stop);
  // Interrupted: keep the rows of every finished clip, even those after a gap, in manifest order.
  for (std::size_t k = next_row; k < done.size(); ++k)
    if (done[k]) write_row(*done[k]);
  summary.interrupted = summary.written < total;
  return summary;
}

}  // namespace echoplan::sim
