// echoplan: plan which sound to make to identify an object, listen, and decide what to do with it.
//
// Exit status: 0 success, 1 internal error, 2 bad input (file, flag or value), 130 interrupted.
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>

#include "commands/commands.h"
#include "common/error.h"

int main(int argc, char** argv) {
  CLI::App app{
      "echoplan: plan which sound to make to identify an object, listen, and decide.\n"
      "Run `echoplan <command> --help` for the options of a command."};
  app.require_subcommand(1);
  app.set_version_flag("--version", ECHOPLAN_VERSION);
  bool verbose = false;
  app.add_flag("-v,--verbose", verbose, "Log debug messages to stderr");
  // Logs and progress go to stderr, so stdout carries only what a command prints as its result.
  spdlog::set_default_logger(spdlog::stderr_color_mt("echoplan"));
  app.parse_complete_callback(
      [&] { spdlog::set_level(verbose ? spdlog::level::debug : spdlog::level::info); });

  echoplan::cli::add_version_command(app);
  echoplan::cli::add_trials_command(app);
  echoplan::cli::add_run_command(app);
  echoplan::cli::add_make_problem_command(app);
  echoplan::cli::add_check_command(app);
  echoplan::cli::add_solve_command(app);
  echoplan::cli::add_certify_command(app);
  echoplan::cli::add_import_command(app);
  echoplan::cli::add_synth_command(app);
  echoplan::cli::add_synth_recordings_command(app);
  echoplan::cli::add_collect_command(app);
  echoplan::cli::add_add_noise_command(app);
  echoplan::cli::add_features_command(app);
  echoplan::cli::add_heatmap_command(app);
  echoplan::cli::add_experiment_command(app);
  echoplan::cli::add_merge_command(app);
  echoplan::cli::add_train_command(app);
  echoplan::cli::add_classify_command(app);
  echoplan::cli::add_evaluate_command(app);
#ifdef ECHOPLAN_HAVE_ROSBAG
  echoplan::cli::add_import_bag_command(app);
#endif
#ifdef ECHOPLAN_HAVE_PORTAUDIO
  echoplan::cli::add_devices_command(app);
  echoplan::cli::add_record_command(app);
#endif

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // CLI11 reports --help as a "success" parse error; usage errors exit 2 like bad input.
    int code = app.exit(e);
    return code == 0 ? 0 : 2;
  } catch (const echoplan::cli::Interrupted&) {
    return 130;
  } catch (const echoplan::InputError& e) {
    std::fprintf(stderr, "echoplan: error: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "echoplan: internal error: %s\n", e.what());
    return 1;
  }
  return 0;
}
