// How every echoplan ROS node ends: its body runs inside run_node, which logs an error with
// ROS_FATAL and turns it into the exit status the `echoplan` command uses (2: bad parameter or
// file, InputError; 1: anything else, e.g. a device or a node that failed).
#pragma once

#include <ros/console.h>

#include <exception>
#include <string>

#include "common/error.h"

namespace echoplan::ros_app {

// Returns body()'s status; `prefix` starts the logged message of a failure other than bad input.
template <typename Body>
int run_node(Body&& body, const std::string& prefix = "") {
  try {
    return body();
  } catch (const InputError& e) {
    ROS_FATAL("%s", e.what());
    return 2;
  } catch (const std::exception& e) {
    ROS_FATAL("%s%s", prefix.c_str(), e.what());
    return 1;
  }
}

}  // namespace echoplan::ros_app
