// The robot: executes the planner's actions in the world and says how they went.
//
// One of the three narrow execution interfaces of the report's architecture (section 4.4): Robot,
// Recorder, ObservationService. The planner side never learns whether the arm is simulated, a real
// arm behind a driver, or a ROS node; each implementation answers the same calls.
#pragma once

#include <cstdint>
#include <string>

#include "sim/action_status.h"

namespace echoplan::robot {

// What the world is told when a trial begins.
struct TrialContext {
  int trial = 0;
  // The true object's name. Simulated and replayed worlds use it to build the scene or choose
  // recordings; a real robot ignores it (an operator placed the object).
  std::string object;
  // Seed of the world's own random stream for this trial (simulated variability, replay choice).
  std::uint64_t seed = 0;
};

// How an action ended: the simulator's status (sim/action_status.h), the same for every robot.
using sim::ActionStatus;
using sim::to_string;

// How one action went. Physical outcomes are reported here, never thrown.
struct ActionReport {
  std::string action;
  ActionStatus status = ActionStatus::done;
  std::string reason;     // for collision and failed: what happened, in words, for the log
  double duration_s = 0;  // from the command to the end of the action (simulated or wall time)
  // For `failed`: the arm stopped before it changed anything (nothing touched, the object where it
  // was), so the same action may be repeated. The loop then retries it (loop/robot_world.h); a
  // failure the arm does not call safe ends the trial.
  bool retry_safe = false;
  // The surface the robot acted on, when it knows and it was chosen (the simulator's table when
  // its config names one: sim/table_choice.h); empty otherwise.
  std::string surface{};
};

class Robot {
 public:
  virtual ~Robot() = default;
  // Prepares a trial: a simulated robot resets its world around `context.object`; a real arm moves
  // to its initial configuration. The world then keeps its state through the trial: a slide moves
  // the object, and the next action starts where the last one ended.
  virtual void begin_trial(const TrialContext& context) = 0;
  // Executes a sensing action ("slide", "strike") or a sorting action (e.g. "move_to_A"), blocking
  // until it has finished. Throws InputError for an action name this robot does not know.
  virtual ActionReport execute(const std::string& action) = 0;
};

}  // namespace echoplan::robot
