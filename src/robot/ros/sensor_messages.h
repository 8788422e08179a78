// sensor_msgs/JointState and geometry_msgs/WrenchStamped to publish from C++20, for a simulated
// arm that reports its sensors as a real arm's driver does (echoplan_sim_robot).
//
// Debian's generated headers for them do not compile as C++20 (ros_messages.h says why), and a
// publisher needs only their layout: these structs declare each type's name, MD5 sum and
// definition and write the same bytes (a std_msgs/Header, then the fields), so any subscriber of
// the standard types (rospy, rosbag, the observation node) reads them. Decoding is
// bag_messages.h's.
#pragma once

#include <ros/serialization.h>
#include <ros/time.h>

#include <cstdint>
#include <string>
#include <vector>

#include "robot/ros/bag_messages.h"
#include "robot/ros/message_type.h"
#include "robot/ros/ros_messages.h"

namespace echoplan::robot {

// std_msgs/Header's fields.
struct StampedHeader {
  std::uint32_t seq = 0;
  ros::Time stamp;
  std::string frame_id;
};

struct JointStateOut {
  StampedHeader header;
  std::vector<std::string> name;
  std::vector<double> position, velocity, effort;
};

struct WrenchStampedOut {
  StampedHeader header;
  double force[3]{};
  double torque[3]{};
};

// The definitions as gendeps writes them (comments left out: the MD5 sums are of the fields).
inline constexpr const char* kJointStateDefinition =
    "Header header\nstring[] name\nfloat64[] position\nfloat64[] velocity\nfloat64[] effort\n\n"
    "================================================================================\n"
    "MSG: std_msgs/Header\nuint32 seq\ntime stamp\nstring frame_id\n";
inline constexpr const char* kWrenchStampedDefinition =
    "Header header\nWrench wrench\n\n"
    "================================================================================\n"
    "MSG: std_msgs/Header\nuint32 seq\ntime stamp\nstring frame_id\n\n"
    "================================================================================\n"
    "MSG: geometry_msgs/Wrench\nVector3  force\nVector3  torque\n\n"
    "================================================================================\n"
    "MSG: geometry_msgs/Vector3\nfloat64 x\nfloat64 y\nfloat64 z";

}  // namespace echoplan::robot

ECHOPLAN_ROS_MESSAGE_TYPE(echoplan::robot::JointStateOut, echoplan::robot::kJointStateType,
                          echoplan::robot::kJointStateMd5, echoplan::robot::kJointStateDefinition)
ECHOPLAN_ROS_MESSAGE_TYPE(echoplan::robot::WrenchStampedOut, echoplan::robot::kWrenchStampedType,
                          echoplan::robot::kWrenchStampedMd5,
                          echoplan::robot::kWrenchStampedDefinition)

namespace ros::serialization {

template <>
struct Serializer<echoplan::robot::StampedHeader> {
  template <typename Stream, typename T>
  inline static void allInOne(Stream& stream, T h) {
    stream.next(h.seq);
    stream.next(h.stamp);
    stream.next(h.frame_id);
  }
  ROS_DECLARE_ALLINONE_SERIALIZER
};

template <>
struct Serializer<echoplan::robot::JointStateOut> {
  template <typename Stream, typename T>
  inline static void allInOne(Stream& stream, T m) {
    stream.next(m.header);
    stream.next(m.name);
    stream.next(m.position);
    stream.next(m.velocity);
    stream.next(m.effort);
  }
  ROS_DECLARE_ALLINONE_SERIALIZER
};

template <>
struct Serializer<echoplan::robot::WrenchStampedOut> {
  template <typename Stream, typename T>
  inline static void allInOne(Stream& stream, T m) {
    stream.next(m.header);
    for (int i = 0; i < 3; ++i) stream.next(m.force[i]);
    for (int i = 0; i < 3; ++i) stream.next(m.torque[i]);
  }
  ROS_DECLARE_ALLINONE_SERIALIZER
};

}  // namespace ros::serialization
