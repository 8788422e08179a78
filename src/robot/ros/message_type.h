// Declaring a struct of echoplan's as a ROS 1 message type: its type name, MD5 sum and definition,
// the traits roscpp reads to publish it, subscribe to it and match it with its peers. For the
// message structs written by hand (string_message.h, sensor_messages.h, raw_message.h), where
// Debian's generated headers do not compile as C++20 or a type is learnt from the publisher.
#pragma once

#include <ros/message_traits.h>

// In the global namespace: ECHOPLAN_ROS_MESSAGE_TYPE(echoplan::robot::X, "pkg/Type", md5, text).
#define ECHOPLAN_ROS_MESSAGE_TYPE(Type, name, md5, definition) \
  namespace ros::message_traits {                              \
  template <>                                                  \
  struct IsMessage<Type> : TrueType {};                        \
  template <>                                                  \
  struct IsMessage<const Type> : TrueType {};                  \
  template <>                                                  \
  struct MD5Sum<Type> {                                        \
    static const char* value() { return md5; }                 \
    static const char* value(const Type&) { return value(); }  \
  };                                                           \
  template <>                                                  \
  struct DataType<Type> {                                      \
    static const char* value() { return name; }                \
    static const char* value(const Type&) { return value(); }  \
  };                                                           \
  template <>                                                  \
  struct Definition<Type> {                                    \
    static const char* value() { return definition; }          \
    static const char* value(const Type&) { return value(); }  \
  };                                                           \
  }
