// A series topic's messages as samples (robot/ros/series_topic.h), from bytes laid out by hand:
// what a bag import and the live observation node both read.
#include "robot/ros/series_topic.h"

#include <gtest/gtest.h>

#include "common/error.h"
#include "robot/ros/bag_messages.h"
#include "robot/ros/sensor_messages.h"
#include "wire_bytes.h"

namespace echoplan::robot {
namespace {

// A joint state naming `names`, with `effort` and one position per joint (velocity empty).
std::vector<std::uint8_t> joint_state(const std::vector<std::string>& names,
                                      const std::vector<double>& effort) {
  Bytes m;
  m.header().u32(static_cast<std::uint32_t>(names.size()));
  for (const std::string& n : names) m.str(n);
  m.u32(static_cast<std::uint32_t>(names.size()));
  for (std::size_t i = 0; i < names.size(); ++i) m.f64(100.0 + static_cast<double>(i));
  m.u32(0);
  m.u32(static_cast<std::uint32_t>(effort.size()));
  for (double e : effort) m.f64(e);
  return m.b;
}

std::vector<std::uint8_t> wrench(double fz, double tx) {
  Bytes w;
  w.header().f64(0).f64(0).f64(fz).f64(tx).f64(0).f64(0);
  return w.b;
}

std::string problem_of(SeriesTopicReader& reader, const std::string& type, const std::string& md5,
                       const std::vector<std::uint8_t>& bytes) {
  try {
    reader.read(type, md5, bytes);
  } catch (const InputError& e) {
    return e.problem();
  }
  ADD_FAILURE() << "read() did not throw";
  return "";
}

TEST(SeriesTopicReader, JointEffortsInTheFirstMessagesJointOrderWhateverTheOrderLater) {
  SeriesTopicReader reader(parse_series_topic("effort=/joint_states"));
  EXPECT_EQ(reader.read(kJointStateType, kJointStateMd5, joint_state({"j1", "j2"}, {1.5, -2.0})),
            (std::vector<double>{1.5, -2.0}));
  EXPECT_EQ(reader.spec().field, "effort");  // the default for a joint state
  EXPECT_EQ(reader.channels(), (std::vector<std::string>{"j1", "j2"}));
  // A driver that lists its joints in another order, with one more: read by name.
  EXPECT_EQ(reader.read(kJointStateType, kJointStateMd5,
                        joint_state({"gripper", "j2", "j1"}, {9.0, 4.0, 3.0})),
            (std::vector<double>{3.0, 4.0}));
  EXPECT_EQ(reader.messages(), 2);
}

TEST(SeriesTopicReader, PositionsAndWrenchFieldsAsAsked) {
  SeriesTopicReader positions(parse_series_topic("angle=/joint_states:position"));
  EXPECT_EQ(positions.read(kJointStateType, kJointStateMd5, joint_state({"a", "b"}, {})),
            (std::vector<double>{100.0, 101.0}));
  SeriesTopicReader force(parse_series_topic("force=/wrist/wrench"));
  EXPECT_EQ(force.read(kWrenchStampedType, kWrenchStampedMd5, wrench(-9.81, 0.5)),
            (std::vector<double>{0.0, 0.0, -9.81}));
  EXPECT_EQ(force.channels(), (std::vector<std::string>{"force_x", "force_y", "force_z"}));
  SeriesTopicReader whole(parse_series_topic("wrench=/wrist/wrench:wrench"));
  EXPECT_EQ(whole.read(kWrenchStampedType, kWrenchStampedMd5, wrench(-9.81, 0.5)),
            (std::vector<double>{0.0, 0.0, -9.81, 0.5, 0.0, 0.0}));
  EXPECT_EQ(whole.channels().back(), "torque_z");
}

TEST(SeriesTopicReader, WhatCannotBeReadIsAnInputErrorSayingWhy) {
  SeriesTopicReader reader(parse_series_topic("effort=/joint_states"));
  EXPECT_EQ(problem_of(reader, kStringType, kStringMd5, {}),
            "a std_msgs/String, not a sensor_msgs/JointState or geometry_msgs/WrenchStamped");
  reader.read(kJointStateType, kJointStateMd5, joint_state({"j1", "j2"}, {1.0, 2.0}));
  EXPECT_EQ(problem_of(reader, kJointStateType, kJointStateMd5, joint_state({"j1"}, {1.0})),
            "no joint 'j2' (the topic's first message had j1, j2)");
  EXPECT_EQ(problem_of(reader, kJointStateType, kJointStateMd5, joint_state({"j1", "j2"}, {1.0})),
            "1 effort values for 2 joints");
  EXPECT_EQ(problem_of(reader, kJointStateType, "0123", joint_state({"j1", "j2"}, {1.0, 2.0})),
            "a sensor_msgs/JointState (MD5 0123), not the sensor_msgs/JointState this reads (MD5 "
            "3066dcd76a6cfaef579bd0f34173e9fd)");
  EXPECT_EQ(problem_of(reader, kWrenchStampedType, kWrenchStampedMd5, wrench(1, 2)),
            "a geometry_msgs/WrenchStamped on a topic of sensor_msgs/JointState");
  SeriesTopicReader torque_of_joints(parse_series_topic("e=/joint_states:torque"));
  EXPECT_EQ(problem_of(torque_of_joints, kJointStateType, kJointStateMd5, joint_state({"a"}, {1})),
            "a sensor_msgs/JointState: its field is effort, position or velocity, not 'torque'");
}

// The messages a simulated arm publishes (sensor_messages.h) are the standard layouts: their bytes
// read back through the reader of the hand-laid ones.
template <typename M>
std::vector<std::uint8_t> serialized(const M& m) {
  std::vector<std::uint8_t> bytes(ros::serialization::serializationLength(m));
  ros::serialization::OStream out(bytes.data(), static_cast<std::uint32_t>(bytes.size()));
  ros::serialization::serialize(out, m);
  return bytes;
}

TEST(SeriesTopicReader, ReadsWhatTheSimulatedArmPublishes) {
  JointStateOut js;
  js.header.frame_id = "base_link";
  js.name = {"j1", "j2"};
  js.effort = {1.25, -3.5};
  SeriesTopicReader efforts(parse_series_topic("effort=/joint_states"));
  EXPECT_EQ(efforts.read(ros::message_traits::DataType<JointStateOut>::value(),
                         ros::message_traits::MD5Sum<JointStateOut>::value(), serialized(js)),
            (std::vector<double>{1.25, -3.5}));
  WrenchStampedOut w;
  w.force[2] = -9.81;
  w.torque[0] = 0.5;
  SeriesTopicReader wrench(parse_series_topic("wrench=/wrist/wrench:wrench"));
  EXPECT_EQ(wrench.read(ros::message_traits::DataType<WrenchStampedOut>::value(),
                        ros::message_traits::MD5Sum<WrenchStampedOut>::value(), serialized(w)),
            (std::vector<double>{0, 0, -9.81, 0.5, 0, 0}));
}

TEST(SeriesTopic, ParsesModalityTopicAndFieldAndRefusesWhatIsNot) {
  const SeriesTopic s = parse_series_topic("force=/wrist/wrench:torque");
  EXPECT_EQ(s.modality, "force");
  EXPECT_EQ(s.topic, "/wrist/wrench");
  EXPECT_EQ(s.field, "torque");
  EXPECT_THROW(parse_series_topic("/joint_states"), InputError);
  EXPECT_THROW(parse_series_topic("audio=/audio/audio"), InputError);
  EXPECT_THROW(parse_series_topic("effort="), InputError);
  EXPECT_THROW(parse_series_topic("ef.fort=/joint_states"), InputError);
}

TEST(PerformanceMarker, StartAndEndReadBackAndOtherTextsAreNotMarkers) {
  const auto start = parse_performance_marker(start_marker_text("mug", "press", "trial3"));
  ASSERT_TRUE(start);
  EXPECT_TRUE(start->start);
  EXPECT_EQ(start->object, "mug");
  EXPECT_EQ(start->action, "press");
  EXPECT_EQ(start->session, "trial3");
  const auto end = parse_performance_marker(" end ");
  ASSERT_TRUE(end);
  EXPECT_FALSE(end->start);
  for (const char* text : {"", "stop", "start mug press", "start mug press s1 extra",
                           "start ../mug press s1", "start mug a/b s1"})
    EXPECT_FALSE(parse_performance_marker(text)) << text;
  EXPECT_THROW(start_marker_text("coffee mug", "press", "trial0"), InputError);
}

}  // namespace
}  // namespace echoplan::robot
