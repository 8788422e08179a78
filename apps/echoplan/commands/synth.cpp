// `echoplan synth`: simulate one action on one object and write what the microphone heard.
#include <fmt/core.h>

#include "audio/io.h"
#include "commands/commands.h"
#include "commands/sim_options.h"
#include "sim/recording.h"

namespace echoplan::cli {

void add_synth_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "synth",
      "Simulate one action (slide or strike) on one object and write the stereo "
      "16-bit recording.\nExample: echoplan synth --object coffee_mug --action strike "
      "--seed 7 -o clip.wav");
  struct Options {
    SimFiles files;
    std::string object, action = "strike", output;
    std::uint64_t seed = 0;
  };
  auto opt = std::make_shared<Options>();
  cmd->add_option("--object", opt->object, "Object name from the catalogue (e.g. coffee_mug)")
      ->required();
  cmd->add_option("--action", opt->action, "slide or strike")->capture_default_str();
  cmd->add_option("--seed", opt->seed,
                  "Seed of every random choice; a dataset's manifest lists each file's seed")
      ->capture_default_str();
  cmd->add_option("-o,--output", opt->output, "WAV (or .flac) file to write")->required();
  add_sim_file_options(*cmd, opt->files);
  cmd->callback([opt] {
    const SimSetup setup = load_sim_setup(opt->files, opt->seed);
    sim::SimulatedRobot robot(setup.catalogue, opt->object, setup.config);
    const sim::SoundAction action = sim::parse_sound_action(opt->action);
    sim::SoundRenderer recorder(robot.object(), robot.table(), setup.config);
    Rng rng(opt->seed);
    const sim::Recording r = sim::simulate_recording(robot, recorder, action, rng);
    audio::write_audio(opt->output, r.clip, audio::write_options_for(opt->output));

    // What happened, for people: the trial's parameters and each impact.
    const auto& out = r.outcome;
    fmt::print("{} {} (seed {}): {:.2f} s simulated, {:.2f} s recorded{}\n", opt->object,
               opt->action, opt->seed, out.duration_s, r.clip.duration_seconds(),
               out.status == sim::ActionStatus::done
                   ? ""
                   : fmt::format(", {}: {}", to_string(out.status), out.reason));
    for (const auto& [name, value] : out.placement.named())
      fmt::print("  {:<17} {:.4g}\n", name, value);
    for (const auto& [name, value] : out.variation.named())
      fmt::print("  {:<17} {:.4g}\n", name, value);
    for (const auto& impact : out.trace.impacts)
      fmt::print("  impact at {:.3f} s: {:.3f} m/s, effective mass {:.3f} kg, contact {:.2f} ms\n",
                 impact.time_s, impact.normal_speed, impact.effective_mass,
                 1e3 * recorder.contact_time(impact));
    fmt::print("wrote {}\n", opt->output);
  });
}

}  // namespace echoplan::cli
