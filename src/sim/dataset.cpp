#include "sim/dataset.h"

#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <memory>

#include "audio/io.h"
#include "common/error.h"
#include "common/rng.h"
#include "sim/simulated_recorder.h"
#include "sim/simulated_robot.h"

namespace echoplan::sim {

namespace {

// FNV-1a: a stable 64-bit hash of a name, so streams do not depend on list order.
std::uint64_t name_hash(const std::string& name) {
  std::uint64_t h = 14695981039346656037ull;
  for (unsigned char c : name) {
    h ^= c;
    h *= 1099511628211ull;
  }
  return h;
}

}  // namespace

std::uint64_t clip_seed(std::uint64_t seed, const std::string& object, const std::string& action,
                        int index) {
  return derive_seed(seed,
                     {name_hash(object), name_hash(action), static_cast<std::uint64_t>(index)});
}

DatasetSummary write_dataset(const Catalogue& catalogue, const SimConfig& config,
                             const DatasetOptions& options,
                             const std::function<void(int, int, const std::string&)>& progress,
                             const std::atomic<bool>& stop) {
  namespace fs = std::filesystem;
  const std::vector<std::string> objects =
      options.objects.empty() ? catalogue.object_names() : options.objects;
  for (const auto& o : objects) catalogue.object(o);  // throws for an unknown name, before any file
  for (const auto& a : options.actions)
    if (a != kSlide && a != kStrike)
      throw InputError("", 0, "unknown action '" + a + "' (known: slide, strike)");
  if (options.per_pair < 1) throw InputError("", 0, "--per-pair must be at least 1");

  const fs::path root(options.output_dir);
  std::error_code ec;
  fs::create_directories(root, ec);
  if (ec)
    throw InputError(options.output_dir, 0, "cannot create the output folder: " + ec.message());
  const fs::path manifest_path = root / "manifest.csv";
  std::ofstream manifest(manifest_path, std::ios::trunc);
  if (!manifest) throw InputError(manifest_path.string(), 0, "cannot write the manifest");
  manifest << "file,object,action,seed,collision,duration_s,impacts";
  for (const auto& [name, value] : ActionVariation{}.named()) manifest << ',' << name;
  for (const auto& [name, value] : TrialSetup{}.named()) manifest << ',' << name;
  manifest << '\n' << std::flush;

  DatasetSummary summary;
  const int total = static_cast<int>(objects.size() * options.actions.size()) * options.per_pair;
  for (const auto& object : objects) {
    // One robot and recorder per object: compiling the MuJoCo scene is the expensive part.
    SimulatedRobot robot(catalogue, object, config);
    SimulatedRecorder recorder(robot.object(), robot.table(), config);
    for (const auto& action : options.actions) {
      const fs::path folder = root / object / action;
      fs::create_directories(folder, ec);
      if (ec) throw InputError(folder.string(), 0, "cannot create the folder: " + ec.message());
      for (int i = 0; i < options.per_pair; ++i) {
        if (stop.load()) {
          summary.interrupted = true;
          return summary;
        }
        const std::uint64_t seed = clip_seed(options.seed, object, action, i);
        Rng rng(seed);
        const Recording r = simulate_recording(robot, recorder, action, rng);
        const std::string relative = fmt::format("{}/{}/{:03d}.wav", object, action, i);
        const fs::path final_path = root / relative;
        const fs::path partial = final_path.string() + ".part";
        audio::write_audio(partial.string(), r.clip, audio::WriteOptions{});
        fs::rename(partial, final_path, ec);
        if (ec)
          throw InputError(final_path.string(), 0,
                           "cannot move the finished file into place: " + ec.message());
        manifest << relative << ',' << object << ',' << action << ',' << seed << ','
                 << (r.outcome.collision() ? 1 : 0) << ','
                 << fmt::format("{:.4f}", r.outcome.duration_s) << ','
                 << r.outcome.trace.impacts.size();
        for (const auto& [name, value] : r.outcome.variation.named())
          manifest << ',' << fmt::format("{:.6g}", value);
        for (const auto& [name, value] : r.outcome.setup.named())
          manifest << ',' << fmt::format("{:.6g}", value);
        manifest << '\n' << std::flush;
        if (!manifest) throw InputError(manifest_path.string(), 0, "cannot write the manifest");
        ++summary.written;
        if (r.outcome.collision()) ++summary.collisions;
        if (progress) progress(summary.written, total, relative);
      }
    }
  }
  return summary;
}

}  // namespace echoplan::sim
