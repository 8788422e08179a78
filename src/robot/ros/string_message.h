// std_msgs/String, the type of the performance markers (series_topic.h), usable from C++20.
//
// Debian's generated std_msgs/String.h names std::allocator<void>::rebind, which C++20 removed,
// so it does not compile here (ros_messages.h says the same of array fields). A string message is
// one length-prefixed string on the wire; this struct declares the same type name, MD5 sum and
// definition, so it talks to any std_msgs/String publisher or subscriber (rospy, rosbag).
#pragma once

#include <ros/serialization.h>

#include <string>

#include "robot/ros/bag_messages.h"
#include "robot/ros/message_type.h"

namespace echoplan::robot {

struct StringMessage {
  std::string data;
};

}  // namespace echoplan::robot

ECHOPLAN_ROS_MESSAGE_TYPE(echoplan::robot::StringMessage, echoplan::robot::kStringType,
                          echoplan::robot::kStringMd5, "string data\n")

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
