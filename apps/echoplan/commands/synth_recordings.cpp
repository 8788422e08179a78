// `echoplan synth-recordings` (formerly `dataset`, still accepted): simulate every (object, action)
// pair several times into a recordings tree with a manifest. "Dataset" is kept for recorded data
// replayed (the dataset world); this writes simulated recordings.
#include <fmt/core.h>

#include "commands/commands.h"
#include "commands/sim_options.h"
#include "common/stop_signal.h"
#include "sim/simulated_recordings.h"

namespace echoplan::cli {

void add_synth_recordings_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "synth-recordings",
      "Simulate and record every (object, action) pair --per-pair times: a recordings tree "
      "DIR/<object>/<action>/NNN.wav and "
      "DIR/manifest.csv "
      "(file, object, action, seed, collision, duration, impacts, sampled parameters, session: "
      "recording i of each action is session i + 1). With --signals effort,force beside audio, the "
      "arm's joint torques and wrist force as NNN.effort.csv and NNN.force.csv (raw signals, "
      "docs/feature-sets.md).\n"
      "Example: echoplan synth-recordings --per-pair 10 --seed 1 -o recordings --objects "
      "coffee_mug,plastic_cup\n"
      "(`echoplan dataset`, its earlier name, still works.)");
  cmd->alias("dataset");
  struct Options {
    SimFiles files;
    sim::SimulatedRecordingsOptions dataset;
  };
  auto opt = std::make_shared<Options>();
  cmd->add_option("--per-pair", opt->dataset.per_pair, "Recordings per (object, action)")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  cmd->add_option("--seed", opt->dataset.seed,
                  "Dataset seed; each file's own seed is in the manifest")
      ->capture_default_str();
  cmd->add_option("-o,--output", opt->dataset.output_dir,
                  "Folder to write (created; its manifest.csv is replaced)")
      ->required();
  cmd->add_option("--objects", opt->dataset.objects,
                  "Objects, comma-separated (default: the whole catalogue)")
      ->delimiter(',');
  cmd->add_option("--threads", opt->dataset.threads,
                  "Worker threads (the files do not depend on it)")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  cmd->add_option("--actions", opt->dataset.actions, "Actions, comma-separated")
      ->delimiter(',')
      ->capture_default_str();
  cmd->add_option("--signals", opt->dataset.signals,
                  "What each performance records, comma-separated: audio (NNN.wav), effort (the "
                  "joint torques j1..j7, NNN.effort.csv), force (the wrist force, NNN.force.csv); "
                  "the sensors' rate and noise are the sim config's `sensors:`")
      ->delimiter(',')
      ->capture_default_str();
  add_sim_file_options(*cmd, opt->files);
  cmd->callback([opt] {
    const SimSetup setup = load_sim_setup(opt->files, opt->dataset.seed);
    // Ctrl-C stops the writer after the clips in progress, so every file on disk is complete and
    // listed in the manifest.
    const StopSignal stop;
    const sim::SimulatedRecordingsSummary summary = sim::write_simulated_recordings(
        setup.catalogue, setup.config, opt->dataset,
        [](const std::string& file, int done, int total) {
          fmt::print(stderr, "[{}/{}] {}\n", done, total, file);
        },
        stop.flag());
    fmt::print(
        "{} recordings in {} ({} with the arm touching the table); manifest: {}/manifest.csv\n",
        summary.written, opt->dataset.output_dir, summary.collisions, opt->dataset.output_dir);
    if (summary.interrupted) {
      fmt::print(
          stderr,
          "echoplan: interrupted; the {} finished recordings and their manifest rows are kept\n",
          summary.written);
      throw Interrupted{};
    }
  });
}

}  // namespace echoplan::cli
