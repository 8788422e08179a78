// The subcommands of `echoplan`. Each add_*_command() adds one subcommand to the app and sets its
// callback; the callback throws echoplan::InputError for bad input (main turns it into exit status
// 2).
#pragma once

#include <CLI/CLI.hpp>

namespace echoplan::cli {

// Thrown by a command that was interrupted (Ctrl-C, see common/stop_signal.h for the one way to
// catch it) after it saved what it had finished; main turns it into exit status 130, the shell's
// convention for SIGINT.
struct Interrupted {};

void add_version_command(CLI::App& app);
void add_trials_command(CLI::App& app);
void add_run_command(CLI::App& app);
void add_make_problem_command(CLI::App& app);
void add_check_command(CLI::App& app);
void add_solve_command(CLI::App& app);
void add_certify_command(CLI::App& app);
void add_import_command(CLI::App& app);  // `import oppt`: another planner's logs
void add_synth_command(CLI::App& app);
void add_synth_recordings_command(CLI::App& app);
void add_collect_command(CLI::App& app);    // a training set collected trial by trial
void add_add_noise_command(CLI::App& app);  // a noisy copy of a recordings tree
void add_features_command(CLI::App& app);
void add_heatmap_command(CLI::App& app);
void add_experiment_command(CLI::App& app);
void add_merge_command(CLI::App& app);
void add_train_command(CLI::App& app);
void add_classify_command(CLI::App& app);
void add_evaluate_command(CLI::App& app);
// ROS 1 bags as a recordings tree (built when rosbag storage is found: ECHOPLAN_HAVE_ROSBAG).
void add_import_bag_command(CLI::App& app);
// Live capture (built when PortAudio is found: ECHOPLAN_HAVE_PORTAUDIO).
void add_devices_command(CLI::App& app);
void add_record_command(CLI::App& app);

}  // namespace echoplan::cli
