// A step and a belief in words, for people watching a loop run (`echoplan run`, the ROS planner
// node): the same lines wherever the loop runs.
#pragma once

#include <string>
#include <vector>

#include "loop/trial_runner.h"
#include "pomdp/model.h"

namespace echoplan::loop {

// "step 2: strike -> heard coffee_mug (p 0.93), 1.2 ms to classify, reward -1"
std::string step_text(const Step& step, const pomdp::ModelSpec& spec);

// What `echoplan run` prints per step: the belief before the first action (at step 0), the step's
// line, and the belief after it (when the trial goes on).
std::string step_report(const Step& step, const pomdp::ModelSpec& spec);

// How a trial ended: "sorted by move_to_B (believed coffee_mug); 2 steps, discounted reward 8.900",
// "ended in a collision; ..." or "no sorting action within the step cap; ...".
std::string trial_text(const Trial& trial, const pomdp::ModelSpec& spec);

// One line per object: its name, a bar and its probability ("    coffee_mug  ████░░  0.250").
std::string belief_text(const std::vector<std::string>& objects, const std::vector<double>& belief);

}  // namespace echoplan::loop
