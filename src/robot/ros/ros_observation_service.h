// An ObservationService behind ROS: each clip goes, with its samples, to the Observe service of
// echoplan_observation, which classifies it with its trained model.
//
// A service node that dies during a call closes the connection, so the call fails at once: a
// TransientError naming the service (the loop skips that performance's observation and re-plans).
// The next call waits up to `wait_timeout_s` for the service (a restarted node comes back); one
// that is not there by then is a std::runtime_error naming the service, which ends the run. An
// error the service reports for the request (no model for the action, bad clip) is an InputError,
// as the interface promises; one it calls transient (the performance could not be sensed: a sensor
// stream stopped) is a TransientError, so the loop skips that observation.
#pragma once

#include <ros/ros.h>

#include <string>

#include "robot/observation_service.h"

namespace echoplan::robot {

class RosObservationService final : public ObservationService {
 public:
  // `node` must outlive the service client.
  RosObservationService(ros::NodeHandle& node, double wait_timeout_s);

  HeardObservation observe(const audio::AudioClip& clip, const std::string& action) override;

 private:
  ros::NodeHandle& node_;
  double wait_timeout_s_;
  ros::ServiceClient client_;
  bool connected_before_ = false;  // a connection was made once: its errors say the node went away
};

}  // namespace echoplan::robot
