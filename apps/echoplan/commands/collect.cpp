// `echoplan collect`: a training set collected the way a robot collects one (loop/collection.h):
// for every object and session a trial in which the arm performs each behaviour in turn while the
// microphone listens, here on the simulated robot, with its joint torques and wrist force when
// asked. Unlike synth-recordings (one fresh trial per recording), a session's behaviours follow
// one another on the same placement, the object where the last one left it.
#include <fmt/core.h>

#include <memory>

#include "commands/commands.h"
#include "commands/sim_options.h"
#include "common/error.h"
#include "common/stop_signal.h"
#include "loop/collection.h"
#include "robot/simulated_world.h"
#include "sim/arm_sensors.h"

namespace echoplan::cli {

namespace {

// The simulated arm's sensors for the performance just executed, as they measured it (with their
// noise, drawn from the trial's own stream: robot/simulated_world.h).
loop::PerformanceSignals arm_signals(std::shared_ptr<robot::SimulatedWorld> world,
                                     std::vector<std::string> wanted) {
  return [world, wanted](const std::string&, int, const std::string&) {
    std::vector<std::pair<std::string, signal::Series>> out;
    if (wanted.empty() || !world->last_outcome()) return out;
    const sim::ArmReadings& readings = world->last_outcome()->readings;
    for (const std::string& w : wanted)
      out.emplace_back(w, w == "effort" ? readings.effort : readings.force);
    return out;
  };
}

}  // namespace

void add_collect_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "collect",
      "Collect a training set as a robot does: for every object and session, one trial in which "
      "the arm performs each behaviour in turn while the microphone listens, written as "
      "DIR/<object>/<action>/sNNN.wav (and, with --signals, sNNN.effort.csv, sNNN.force.csv) "
      "with DIR/manifest.csv (file, object, action, session, status). Resumable: run it again "
      "on the same folder and it goes on where it stopped. Here on the simulated robot (a real arm "
      "over ROS: the echoplan_collector node, docs/real-robot.md).\n"
      "Example: echoplan collect --objects coffee_mug,plastic_cup --sessions 10 -o tree "
      "--signals effort,force");
  struct Options {
    SimFiles files;
    loop::CollectionPlan plan;
    std::vector<std::string> signals;
  };
  auto opt = std::make_shared<Options>();
  opt->plan.behaviours = robot::SimulatedWorld::sensing_actions();
  cmd->add_option("--objects", opt->plan.objects, "Objects, comma-separated (catalogue names)")
      ->delimiter(',')
      ->required();
  cmd->add_option("--sessions", opt->plan.sessions, "Sessions per object")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  cmd->add_option("--behaviours", opt->plan.behaviours,
                  "The behaviours each session performs, in order, comma-separated")
      ->delimiter(',')
      ->capture_default_str();
  cmd->add_option("--seed", opt->plan.seed, "Seed of the trials (placement, variability, noise)")
      ->capture_default_str();
  cmd->add_option("-o,--output", opt->plan.output_dir, "Folder to write (or to resume)")
      ->required();
  cmd->add_option("--signals", opt->signals,
                  "Besides audio, comma-separated: effort (joint torques), force (wrist force)")
      ->delimiter(',')
      ->check(CLI::IsMember({"effort", "force"}));
  add_sim_file_options(*cmd, opt->files);
  cmd->callback([opt] {
    SimSetup setup = load_sim_setup(opt->files, opt->plan.seed);
    auto world = std::make_shared<robot::SimulatedWorld>(
        std::move(setup.catalogue), std::move(setup.config), std::vector<std::string>{});
    for (const auto& o : opt->plan.objects) world->check_object(o);
    for (const auto& b : opt->plan.behaviours) world->check_action(b);
    robot::SimulatedArm arm(world);
    robot::SimulatedMicrophone microphone(world);
    const StopSignal stop;
    const loop::CollectionSummary summary = loop::collect(
        arm, &microphone, opt->plan, arm_signals(world, opt->signals),
        [](const loop::CollectionStep& s) {
          fmt::print(stderr, "[{}/{}] {} session {} {}\n", s.done, s.total, s.object, s.session,
                     s.behaviour);
        },
        stop.flag());
    fmt::print(
        "{} performances recorded, {} already there ({} not done as planned: see the "
        "manifest's status); manifest: {}/manifest.csv\n",
        summary.performed, summary.kept, summary.failed, opt->plan.output_dir);
    if (summary.interrupted) {
      fmt::print(stderr, "echoplan: interrupted; run the same command again to go on\n");
      throw Interrupted{};
    }
  });
}

}  // namespace echoplan::cli
