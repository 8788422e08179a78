#include "sim/action_status.h"

namespace echoplan::sim {

const char* to_string(ActionStatus status) {
  switch (status) {
    case ActionStatus::done:
      return "done";
    case ActionStatus::collision:
      return "collision";
    case ActionStatus::failed:
      return "failed";
  }
  return "unknown";
}

}  // namespace echoplan::sim
