#include "robot/ros/performance_marks.h"

#include <fmt/format.h>

#include "robot/ros/series_topic.h"
#include "robot/ros/string_message.h"

namespace echoplan::robot {

namespace {

// A subscriber that connects after a marker was published never gets it, and the observation node
// subscribes when it starts, which may be just after the planner: the first marker waits this long
// for one. A node that is up connects within milliseconds; a layout with nobody listening (a robot
// publishing feature rows) pays this once per run.
constexpr double kSubscriberWaitS = 1.0;

}  // namespace

MarkedRobot::MarkedRobot(ros::NodeHandle& node, std::unique_ptr<Robot> inner,
                         std::set<std::string> sensing, const std::string& topic)
    : inner_(std::move(inner)),
      sensing_(std::move(sensing)),
      markers_(node.advertise<StringMessage>(topic, 16)) {}

void MarkedRobot::begin_trial(const TrialContext& context) {
  context_ = context;
  inner_->begin_trial(context);
}

void MarkedRobot::publish(const std::string& text) {
  if (!waited_) {
    const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(kSubscriberWaitS);
    while (markers_.getNumSubscribers() == 0 && ros::ok() && ros::WallTime::now() < deadline)
      ros::WallDuration(0.005).sleep();
    waited_ = true;
  }
  StringMessage message;
  message.data = text;
  markers_.publish(message);
}

ActionReport MarkedRobot::execute(const std::string& action) {
  if (!sensing_.contains(action)) return inner_->execute(action);
  publish(start_marker_text(context_.object.empty() ? "object" : context_.object, action,
                            fmt::format("trial{}", context_.trial)));
  ActionReport report = inner_->execute(action);
  publish("end");
  return report;
}

}  // namespace echoplan::robot
