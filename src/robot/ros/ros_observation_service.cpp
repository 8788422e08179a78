#include "robot/ros/ros_observation_service.h"

#include <fmt/format.h>

#include <stdexcept>

#include "common/error.h"
#include "robot/ros/clip_message.h"
#include "robot/ros/master_watch.h"
#include "robot/ros/ros_messages.h"
#include "robot/ros/ros_protocol.h"
#include "robot/transient_error.h"

namespace echoplan::robot {

RosObservationService::RosObservationService(ros::NodeHandle& node, double wait_timeout_s)
    : node_(node), wait_timeout_s_(wait_timeout_s) {}

HeardObservation RosObservationService::observe(const audio::AudioClip& clip,
                                                const std::string& action) {
  const char* name = ros_names::kObserveService;
  if (!client_ || !client_.isValid()) {
    // Not connected yet, or the node died (a failed call closed the connection): wait for it, a
    // node restarted by its launch file or an operator comes back within the wait.
    if (!ros::service::waitForService(name, ros::Duration(wait_timeout_s_)))
      throw std::runtime_error(
          connected_before_
              ? fmt::format("the observation service {} went away and did not come back within "
                            "{:g} s (did echoplan_observation die?){}",
                            name, wait_timeout_s_, master_unreachable_note())
              : fmt::format("the observation service {} is not available (waited {:g} s; is "
                            "echoplan_observation running?){}",
                            name, wait_timeout_s_, master_unreachable_note()));
    client_ = node_.serviceClient<echoplan_ros::Observe>(name, true);
    connected_before_ = true;
  }
  echoplan_ros::Observe call;
  call.request.action = action;
  fill_request(clip, call.request);
  if (!client_.call(call)) {
    // This performance goes unheard; the next call waits for the node to come back.
    client_.shutdown();
    throw TransientError(fmt::format(
        "the call to the observation service {} for '{}' failed (the node died or refused it)",
        name, action));
  }
  const auto& r = call.response;
  if (!r.error.empty() && r.transient)
    throw TransientError(fmt::format("{}: '{}' could not be sensed: {}", name, action, r.error));
  if (!r.error.empty()) throw InputError(name, 0, r.error);
  if (r.classes.size() != r.probabilities.size())
    throw std::runtime_error(fmt::format("{} answered {} classes but {} probabilities", name,
                                         r.classes.size(), r.probabilities.size()));
  HeardObservation heard;
  heard.label = r.label;
  heard.unknown = r.unknown;
  heard.probability = r.probability;
  heard.grade = r.grade;
  heard.level_grade = r.level_grade;
  heard.distance = r.distance;
  for (std::size_t i = 0; i < r.classes.size(); ++i)
    heard.probabilities.emplace_back(r.classes[i], r.probabilities[i]);
  return heard;
}

}  // namespace echoplan::robot
