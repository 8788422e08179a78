// How an action ended: the one status every robot reports (the simulator's, a real arm's, a ROS
// node's). The robot module brings it in as robot::ActionStatus.
#pragma once

namespace echoplan::sim {

enum class ActionStatus {
  done,       // ran to its end
  collision,  // the arm (or the object) touched the table or the workspace; the action stopped
              // there
  failed,     // not carried out: the object is out of reach or has fallen over, a driver error, ...
};

// "done", "collision", "failed".
const char* to_string(ActionStatus status);

}  // namespace echoplan::sim
