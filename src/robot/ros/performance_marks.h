// A Robot that says on a ROS topic when each sensing action begins and ends: `start OBJECT ACTION
// SESSION` before the inner robot executes it and `end` after it answered (std_msgs/String on
// /echoplan/performance by default; series_topic.h). The observation node cuts a robot's joint
// state and wrench streams between them (robot/performance_streams.h), and a bag recorded with
// them imports as a recordings tree (bag_import.h) that replays the same performances.
//
// OBJECT is the trial's true object as the planner knows it (the operator's, or the simulated
// robot's), SESSION `trial<N>` for trial N. Sorting actions are not marked.
#pragma once

#include <ros/ros.h>

#include <memory>
#include <set>
#include <string>

#include "robot/robot.h"

namespace echoplan::robot {

class MarkedRobot final : public Robot {
 public:
  // `node` must outlive the robot; `sensing`: the actions to mark; `topic`: where (normally
  // ros_names::kPerformanceTopic).
  MarkedRobot(ros::NodeHandle& node, std::unique_ptr<Robot> inner, std::set<std::string> sensing,
              const std::string& topic);

  void begin_trial(const TrialContext& context) override;
  // Marks a sensing action around the inner robot's execute(); an end is published even when the
  // action failed (a bag then holds that performance too; the observation node uses only the
  // performance the planner asks for).
  ActionReport execute(const std::string& action) override;

 private:
  void publish(const std::string& text);

  std::unique_ptr<Robot> inner_;
  std::set<std::string> sensing_;
  ros::Publisher markers_;
  TrialContext context_;
  bool waited_ = false;  // for a subscriber, before the first marker
};

}  // namespace echoplan::robot
