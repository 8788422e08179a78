// A fault in one step of the loop with a robot: what went wrong, and what the loop did about it.
//
// A real arm, microphone and classifier fail in ways the model never does. RobotWorld turns each
// such failure into a StepFault on the step instead of an exception that would end the whole run,
// and the trial runner acts on its effect:
//   observation_skipped  the action was done but nothing trustworthy was heard (an empty, silent,
//                        clipped or short recording, one of another format, a capture device that
//                        went away, a service that failed or answered a class the problem does not
//                        know): the belief is not updated and the planner re-plans from it, so no
//                        sorting decision rests on evidence the loop did not get;
//   trial_failed         the arm reported the action failed (stopped midway, timed out) and did not
//                        say it was safe to repeat it, or failed on every attempt: the trial ends
//                        as the model's collision ends it.
// Configuration mistakes (an action the robot or the service does not know) stay InputErrors, and
// a part that is gone for good (a ROS node that died) still ends the run: only a failure a part
// calls transient (robot/transient_error.h) is a step's fault.
#pragma once

#include <string>

namespace echoplan::loop {

enum class FaultEffect { observation_skipped, trial_failed };

struct StepFault {
  std::string kind;    // what failed, in a few fixed words: "recording silent", "action failed"
  std::string detail;  // the measurement or the part's own message
  FaultEffect effect = FaultEffect::observation_skipped;
};

// "trial 3, step 2 (strike): recording silent (peak 0 dBFS ...); the observation is skipped and
// the planner re-plans" - the line the user sees, naming the fault, the trial and the step (both
// as logged: 0-based trial, 1-based step as `echoplan run` prints it).
std::string fault_text(int trial, int step, const std::string& action, const StepFault& fault);

}  // namespace echoplan::loop
