// echoplan_planner: the original system's planner process. Runs trials of the closed loop (plan,
// execute, listen, classify, update the belief) with the arm, the listener and the observation
// service behind ROS:
// - robot: /echoplan/begin_trial and /echoplan/execute_action (a real arm's driver or
//   echoplan_sim_robot)
// - recorder: the parameter /echoplan/record around each sensing action (echoplan_listener)
// - service: /echoplan/observe (echoplan_observation)
// The loop itself is the in-process one (loop::Loop, see loop_trials.h), so a ROS run and
// `echoplan run` plan, log and score the same way.
//
// Private parameters:
//   ~problem      problem YAML to plan on (required; its observation table should be the model's,
//                 docs/real-robot.md)
//   ~out          folder for loop_steps.csv, loop_steps.jsonl and the clips (required)
//   ~trials (1), ~max_steps (100), ~seed (1)
//   ~object       the true object (placed by the operator; built by the simulated robot); empty:
//                 drawn per trial from the problem's initial belief. With it, trial 0 logs exactly
//                 what `echoplan run --object` logs with the same seed, problem, model and budget
//   ~solver, ~episodes, ~step_ms   the planner and its budget per step (default: the
//                 problem file's)
//   ~wait_timeout_s  how long to wait for a node to appear or answer before failing (10)
//   ~listen       true (default): record each sensing action with echoplan_listener; false: the
//                 robot has no microphone, so no listener is run, the record parameter is left
//                 alone and echoplan_observation observes each performance from the robot's
//                 feature topic or sensor streams alone (docs/real-robot.md)
//
// Around each sensing action it publishes `start OBJECT ACTION trial<N>` and `end` on
// /echoplan/performance (robot/ros/performance_marks.h): where the observation node cuts a robot's
// sensor streams, and what makes a bag recorded of the run importable (`echoplan import-bag`).
//
// Exits 0 when every trial finished, 2 for bad parameters or files, 1 when a node failed (died,
// never answered), with the reason logged.
#include <fmt/format.h>
#include <ros/ros.h>

#include <memory>
#include <set>
#include <string>

#include "common/error.h"
#include "loop/object_problem.h"
#include "loop_trials.h"
#include "node_main.h"
#include "pomdp/problem.h"
#include "robot/ros/master_watch.h"
#include "robot/ros/performance_marks.h"
#include "robot/ros/ros_observation_service.h"
#include "robot/ros/ros_protocol.h"
#include "robot/ros/ros_recorder.h"
#include "robot/ros/ros_robot.h"

namespace {

// The sensing actions of the problem in `path` (the ones the planner marks).
std::set<std::string> sensing_actions(const std::string& path) {
  const echoplan::pomdp::Problem problem = echoplan::pomdp::load_problem(path);
  std::set<std::string> names;
  for (const auto& a : echoplan::loop::object_problem(*problem.model).data().sensing)
    names.insert(a.name);
  return names;
}

}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "echoplan_planner");
  ros::NodeHandle node;
  ros::NodeHandle priv("~");
  // The recorder's answers (recording state, clips) arrive while the trial loop blocks on this
  // thread.
  ros::AsyncSpinner spinner(1);
  spinner.start();
  return echoplan::ros_app::run_node(
      [&] {
        echoplan::ros_app::LoopTrialSettings settings;
        int episodes = 0, step_ms = 0;
        double wait_timeout_s = 10.0;
        std::string seed_text = "1";
        if (!priv.getParam("problem", settings.problem))
          throw echoplan::InputError("~problem", 0,
                                     "the parameter is required: the problem YAML to plan on");
        if (!priv.getParam("out", settings.out))
          throw echoplan::InputError("~out", 0,
                                     "the parameter is required: the folder for the logs");
        priv.param("trials", settings.trials, 1);
        priv.param<std::string>("object", settings.object, "");
        priv.param("max_steps", settings.max_steps, 100);
        // XML-RPC integers are 32-bit: a larger seed is given as a string
        // ("_seed:='\"12345678901\"'").
        if (int small_seed = 0; priv.getParam("seed", small_seed)) {
          if (small_seed < 0)
            throw echoplan::InputError("~seed", 0, fmt::format("must be >= 0, got {}", small_seed));
          seed_text = std::to_string(small_seed);
        } else {
          priv.getParam("seed", seed_text);
        }
        priv.param<std::string>("solver", settings.solver, "");
        priv.param("episodes", episodes, 0);
        priv.param("step_ms", step_ms, 0);
        priv.param("wait_timeout_s", wait_timeout_s, 10.0);
        try {
          settings.seed = std::stoull(seed_text);
        } catch (const std::exception&) {
          throw echoplan::InputError("~seed", 0,
                                     fmt::format("'{}' is not a non-negative integer", seed_text));
        }
        settings.episodes = episodes;
        settings.step_ms = step_ms;

        // A call that needs the master (setting the record parameter) waits for it no longer
        // than for a node, so a master that does not come back stops the run instead of hanging.
        ros::master::setRetryTimeout(ros::WallDuration(wait_timeout_s));
        echoplan::loop::RobotParts parts;
        parts.robot = std::make_unique<echoplan::robot::MarkedRobot>(
            node,
            std::make_unique<echoplan::robot::RosRobot>(node, wait_timeout_s,
                                                        /*begin_trial_required=*/false),
            sensing_actions(settings.problem), echoplan::robot::ros_names::kPerformanceTopic);
        bool listen = true;
        priv.param("listen", listen, true);
        if (listen)
          parts.recorder = std::make_unique<echoplan::robot::RosRecorder>(node, wait_timeout_s);
        parts.service =
            std::make_unique<echoplan::robot::RosObservationService>(node, wait_timeout_s);
        const echoplan::robot::MasterWatch watch;  // its subscriptions: the recorder's
        const auto trials = echoplan::ros_app::run_loop_trials(
            settings, std::move(parts),
            [](const std::string& line) { ROS_INFO("%s", line.c_str()); });
        ROS_INFO("%zu trial(s) finished; logs in %s", trials.size(), settings.out.c_str());
        return 0;
      },
      "trial stopped: ");
}
