// A robot's sensor streams on ROS (sensor_msgs/JointState, geometry_msgs/WrenchStamped topics, read
// as robot/ros/series_topic.h says) and the performance markers the planner or the collector
// publishes around each sensing action, cut into performances (robot/performance_streams.h): what
// echoplan_observation computes features from and echoplan_collector writes as series files.
#pragma once

#include <ros/callback_queue.h>
#include <ros/ros.h>

#include <chrono>
#include <optional>
#include <string>
#include <vector>

#include "robot/performance_streams.h"
#include "robot/ros/raw_message.h"
#include "robot/ros/series_topic.h"
#include "robot/ros/string_message.h"
#include "signal/series.h"

namespace echoplan::ros_app {

// A private parameter holding several words: a list of texts (a launch file's rosparam) or one
// text separated by commas or spaces (the command line, where roscpp reads no lists). Nothing when
// it is not set; InputError naming ~NAME when it is neither.
std::optional<std::vector<std::string>> words_param(ros::NodeHandle& priv, const char* name);

// The private parameter ~series: MODALITY=TOPIC[:FIELD] entries (words_param). Empty when not set.
// InputError naming ~series for a malformed entry or a modality named twice.
std::vector<robot::SeriesTopic> series_param(ros::NodeHandle& priv);

class SensorStreams {
 public:
  // Subscribes to each topic and to `marker_topic`, on a queue and a thread of their own (so that
  // a request waiting for its performance does not block them), handled in the order they
  // arrived. `node` must outlive this.
  SensorStreams(ros::NodeHandle& node, std::vector<robot::SeriesTopic> topics,
                const std::string& marker_topic);

  // The topics, in the order take() numbers them.
  const std::vector<robot::SeriesTopic>& topics() const { return topics_; }
  // The series of `streams` (indices into topics()) in the performance of `action` that ended
  // last, waiting up to `timeout` for its end marker. InputError as PerformanceStreams::take says.
  std::vector<signal::Series> take(const std::string& action,
                                   const std::vector<std::size_t>& streams,
                                   std::chrono::milliseconds timeout) {
    return streams_.take(action, streams, timeout);
  }

 private:
  void on_marker(const ros::MessageEvent<const robot::StringMessage>& event);
  void on_message(std::size_t stream, const ros::MessageEvent<const robot::RawMessage>& event);

  const std::vector<robot::SeriesTopic> topics_;
  const std::string marker_topic_;
  std::vector<robot::SeriesTopicReader> readers_;  // used on the subscription thread only
  robot::PerformanceStreams streams_;
  ros::CallbackQueue queue_;
  std::vector<ros::Subscriber> subs_;
  std::optional<ros::AsyncSpinner> spinner_;
};

// A duration given as seconds, from private parameter `name` (InputError unless > 0).
std::chrono::milliseconds seconds_param(ros::NodeHandle& priv, const char* name, double fallback);

}  // namespace echoplan::ros_app
