// A message of any type, kept as its serialized bytes: what a subscriber gets when it subscribes
// to a topic whose type it learns only from the publisher (a series topic may carry joint states
// or wrenches, robot/ros/series_topic.h), as rosbag records them. Subscribe with a
// ros::MessageEvent<const RawMessage> callback: its connection header names the publisher's type
// ("type") and layout ("md5sum").
//
// Why not topic_tools::ShapeShifter, which does this: Debian ships it only with the topic_tools
// nodes' package, and what it adds (republishing) is not needed; this is the part of it used.
#pragma once

#include <ros/serialization.h>

#include <cstdint>
#include <vector>

#include "robot/ros/message_type.h"

namespace echoplan::robot {

struct RawMessage {
  std::vector<std::uint8_t> bytes;
};

}  // namespace echoplan::robot

// "*": any type and layout, as roscpp's own generic subscribers declare.
ECHOPLAN_ROS_MESSAGE_TYPE(echoplan::robot::RawMessage, "*", "*", "")

namespace ros::serialization {

template <>
struct Serializer<echoplan::robot::RawMessage> {
  template <typename Stream>
  static void read(Stream& stream, echoplan::robot::RawMessage& m) {
    const std::uint32_t n = stream.getLength();
    const std::uint8_t* data = stream.advance(n);
    m.bytes.assign(data, data + n);
  }
  template <typename Stream>
  static void write(Stream& stream, const echoplan::robot::RawMessage& m) {
    const auto n = static_cast<std::uint32_t>(m.bytes.size());
    if (n > 0) std::copy(m.bytes.begin(), m.bytes.end(), stream.advance(n));
  }
  static std::uint32_t serializedLength(const echoplan::robot::RawMessage& m) {
    return static_cast<std::uint32_t>(m.bytes.size());
  }
};

}  // namespace ros::serialization
