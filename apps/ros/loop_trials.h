// The closed loop's trials over any Robot, Recorder and ObservationService: the part of
// `echoplan_planner` that does not know about ROS. The planner node calls it with the ROS clients
// (robot/ros/); the ros_* tests call it with the in-process parts to get the log the in-process
// loop writes. Both go through the same loop::Loop and LoopLog as `echoplan run`.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "loop/robot_world.h"
#include "loop/trial_record.h"

namespace echoplan::ros_app {

struct LoopTrialSettings {
  std::string problem;  // problem YAML the planner plans on (its observation table: the model's)
  std::string solver;   // empty: the problem file's
  std::int64_t episodes =
      0;  // search episodes per step (deterministic); 0: the problem file's budget
  std::int64_t step_ms = 0;  // or wall time per step
  int trials = 1;            // number of trials
  // The true object (a problem object): the one an operator placed on a real robot, the one the
  // simulated robot builds. Empty: each trial draws it from the problem's initial belief. When set,
  // trial t's streams are those of `echoplan run --seed` (derived with its trial stream), so trial
  // 0 writes the same log as `echoplan run --object OBJECT` with the same problem, model and
  // budget.
  std::string object;
  int max_steps = 100;
  std::uint64_t seed = 1;
  std::string out;  // LoopLog folder: loop_steps.csv, loop_steps.jsonl, clips/
};

// Latencies of the loop's sensing steps, in milliseconds, one entry per step.
struct LoopTimings {
  std::vector<double>
      action_end_to_belief_ms;     // the robot's answer -> the belief updated (recording
                                   // stopped, clip delivered, classified, belief updated)
  std::vector<double> observe_ms;  // of which the observation service call
  std::vector<double>
      capture_start_ms;  // recorder start() (ROS: parameter set -> listener capturing)
};

// Runs the trials, writing the LoopLog and telling `say` one line per step and per trial (as
// `echoplan run` prints them). Throws InputError for bad settings and whatever a part throws (a
// node that died: std::runtime_error naming it), after logging the steps finished so far.
std::vector<loop::TrialRecord> run_loop_trials(const LoopTrialSettings& settings,
                                               loop::RobotParts parts,
                                               const std::function<void(const std::string&)>& say,
                                               const std::atomic<bool>* stop_requested = nullptr,
                                               LoopTimings* timings = nullptr);

}  // namespace echoplan::ros_app
