// A failure of one call of a part that the next call may not have: a capture device that went away
// and may come back, a classifier that did not answer in time. A Recorder or an ObservationService
// throws it for such a failure; the loop then skips the step's observation and goes on
// (loop/step_fault.h). Any other exception from a part (a ROS node that died, bad input) ends the
// run as before, with the finished steps kept.
#pragma once

#include <stdexcept>

namespace echoplan::robot {

class TransientError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace echoplan::robot
