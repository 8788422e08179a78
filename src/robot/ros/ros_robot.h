// A Robot whose arm is behind ROS: each action is a call to the ExecuteAction service of an arm
// driver (a real arm's, or echoplan_sim_robot), each trial begins with a call to BeginTrial.
//
// Calls block until the driver answers. A driver that is not there (yet) is waited for up to
// `wait_timeout_s`; a driver that dies during a call closes its connection, so the call fails at
// once. Both are std::runtime_error naming the service, never a hang or a silent outcome. Physical
// outcomes (collision, failure, and whether a failure is safe to repeat: the reply's retry_safe)
// come back as ActionReports, as the Robot interface promises. The connections are persistent, so
// a restarting ROS master does not interrupt them; a connection lost while the master does not
// answer is waited for (up to `wait_timeout_s`) rather than taken for a dead driver.
#pragma once

#include <ros/ros.h>

#include <set>
#include <string>

#include "robot/robot.h"

namespace echoplan::robot {

class RosRobot final : public Robot {
 public:
  // `node` must outlive the robot. `begin_trial_required`: when false, a driver without the
  // BeginTrial service is accepted (an arm an operator resets by hand) and begin_trial() only logs.
  RosRobot(ros::NodeHandle& node, double wait_timeout_s, bool begin_trial_required);

  void begin_trial(const TrialContext& context) override;
  // Throws InputError when the driver reports FAILED with reason "unknown action ...": the Robot
  // interface's contract for an action name the robot does not know.
  ActionReport execute(const std::string& action) override;

 private:
  ros::ServiceClient& connected(ros::ServiceClient& client, const char* name);

  ros::NodeHandle& node_;
  double wait_timeout_s_;
  bool begin_trial_required_;
  ros::ServiceClient execute_;
  ros::ServiceClient begin_trial_;
  std::set<std::string> connected_;  // services connected once: losing one means the driver died
};

}  // namespace echoplan::robot
