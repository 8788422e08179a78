// std_msgs/String, the type of the performance markers (series_topic.h), usable from C++20.
//
// Debian's generated std_msgs/String.h names std::allocator<void>::rebind, which C++20 removed,
// so it does not compile here (ros_messages.h says the same of array fields). A string message is
// one length-prefixed string on the wire; this struct declares the same type name, MD5 sum and
// definition, so it talks to any std_msgs/String publisher or subscriber (rospy, rosbag).
#pragma once

#include <ros/message_traits.h>
#include <ros/serialization.h>

#include <string>

#include "robot/ros/bag_messages.h"

namespace echoplan::robot {

struct StringMessage {
  std::string data;
};

}  // namespace echoplan::robot

namespace ros::message_traits {

template <>
struct IsMessage<echoplan::robot::StringMessage> : TrueType {};
template <>
struct IsMessage<const echoplan::robot::StringMessage> : TrueType {};
template <>
struct MD5Sum<echoplan::robot::StringMessage> {
  static const char* value() { return echoplan::robot::kStringMd5; }
  static const char* value(const echoplan::robot::StringMessage&) { return value(); }
};
template <>
struct DataType<echoplan::robot::StringMessage> {
  static const char* value() { return "std_msgs/String"; }
  static const char* value(const echoplan::robot::StringMessage&) { return value(); }
};
template <>
struct Definition<echoplan::robot::StringMessage> {
  static const char* value() { return "string data\n"; }
  static const char* value(const echoplan::robot::StringMessage&) { return value(); }
};

}  // namespace ros::message_traits

namespace ros::serialization {

template <>
struct Serializer<echoplan::robot::StringMessage> {
  template <typename Stream, typename T>
  inline static void allInOne(Stream& stream, T m) {
    stream.next(m.data);
  }
  ROS_DECLARE_ALLINONE_SERIALIZER
};

}  // namespace ros::serialization
