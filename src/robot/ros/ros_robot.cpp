#include "robot/ros/ros_robot.h"

#include <fmt/format.h>

#include <stdexcept>

#include "common/error.h"
#include "robot/ros/master_watch.h"
#include "robot/ros/ros_messages.h"
#include "robot/ros/ros_protocol.h"

namespace echoplan::robot {

RosRobot::RosRobot(ros::NodeHandle& node, double wait_timeout_s, bool begin_trial_required)
    : node_(node), wait_timeout_s_(wait_timeout_s), begin_trial_required_(begin_trial_required) {}

// A persistent connection (one TCP connection for the whole run, no master lookup per call) that is
// re-made when it broke; waits for the service to appear up to the timeout.
ros::ServiceClient& RosRobot::connected(ros::ServiceClient& client, const char* name) {
  if (client && client.isValid()) return client;
  // A persistent connection that closed means the driver went away: fail now unless it is back.
  // Only the master can tell, so while it does not answer (restarting) the service is waited for.
  if (connected_.count(name) > 0 && ros::master::check() && !ros::service::exists(name, false))
    throw std::runtime_error(fmt::format(
        "the robot's service {} went away (its connection closed; did the driver die?)", name));
  if (!ros::service::waitForService(name, ros::Duration(wait_timeout_s_)))
    throw std::runtime_error(
        fmt::format("the robot's service {} is not available (waited {:g} s){}", name,
                    wait_timeout_s_, master_unreachable_note()));
  if (std::string(name) == ros_names::kExecuteActionService)
    client = node_.serviceClient<echoplan_ros::ExecuteAction>(name, true);
  else
    client = node_.serviceClient<echoplan_ros::BeginTrial>(name, true);
  connected_.insert(name);
  return client;
}

void RosRobot::begin_trial(const TrialContext& context) {
  // Wait for the driver itself first: a driver serves BeginTrial, if at all, from the moment it
  // serves ExecuteAction (echoplan_sim_robot advertises BeginTrial first).
  connected(execute_, ros_names::kExecuteActionService);
  // A driver already connected to needs no lookup: the master may be restarting meanwhile, and a
  // lookup that fails then must not be taken for a driver without BeginTrial.
  const bool connected_before = begin_trial_ && begin_trial_.isValid();
  if (!begin_trial_required_ && !connected_before &&
      !ros::service::exists(ros_names::kBeginTrialService, false)) {
    ROS_INFO("trial %d: no %s service; the arm is expected at its initial configuration",
             context.trial, ros_names::kBeginTrialService);
    return;
  }
  echoplan_ros::BeginTrial call;
  call.request.trial = context.trial;
  call.request.object = context.object;
  call.request.seed = context.seed;
  if (!connected(begin_trial_, ros_names::kBeginTrialService).call(call)) {
    begin_trial_.shutdown();
    throw std::runtime_error(
        fmt::format("the call to {} failed (the robot node died or refused it)",
                    ros_names::kBeginTrialService));
  }
  if (!call.response.ok)
    throw std::runtime_error(
        fmt::format("the robot cannot begin trial {}: {}", context.trial, call.response.reason));
}

ActionReport RosRobot::execute(const std::string& action) {
  echoplan_ros::ExecuteAction call;
  call.request.action = action;
  if (!connected(execute_, ros_names::kExecuteActionService).call(call)) {
    execute_.shutdown();
    throw std::runtime_error(
        fmt::format("the call to {} for '{}' failed (the robot node died or refused it)",
                    ros_names::kExecuteActionService, action));
  }
  const auto& r = call.response;
  ActionReport report;
  report.action = action;
  report.reason = r.reason;
  report.duration_s = r.duration_s;
  report.retry_safe = r.retry_safe;
  switch (r.status) {
    case echoplan_ros::ExecuteAction::Response::DONE:
      report.status = ActionStatus::done;
      break;
    case echoplan_ros::ExecuteAction::Response::COLLISION:
      report.status = ActionStatus::collision;
      break;
    case echoplan_ros::ExecuteAction::Response::FAILED:
      if (r.reason.rfind("unknown action", 0) == 0)
        throw InputError(ros_names::kExecuteActionService, 0, r.reason);
      report.status = ActionStatus::failed;
      break;
    default:
      throw std::runtime_error(
          fmt::format("{} answered '{}' with status {}, which is not DONE, COLLISION or FAILED",
                      ros_names::kExecuteActionService, action, static_cast<int>(r.status)));
  }
  return report;
}

}  // namespace echoplan::robot
