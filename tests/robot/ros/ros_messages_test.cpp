// Reading ROS messages off the wire (robot/ros/ros_messages.h's array deserializers): a body that
// announces more elements than it holds is refused before anything is allocated.
#include "robot/ros/ros_messages.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <vector>

namespace echoplan::robot {
namespace {

// The serialized body of `message`.
template <typename Message>
std::vector<std::uint8_t> serialize(const Message& message) {
  std::vector<std::uint8_t> body(ros::serialization::serializationLength(message));
  ros::serialization::OStream stream(body.data(), static_cast<std::uint32_t>(body.size()));
  ros::serialization::serialize(stream, message);
  return body;
}

template <typename Message>
void deserialize(std::vector<std::uint8_t>& body, Message& message) {
  ros::serialization::IStream stream(body.data(), static_cast<std::uint32_t>(body.size()));
  ros::serialization::deserialize(stream, message);
}

void set_u32(std::vector<std::uint8_t>& body, std::size_t at, std::uint32_t value) {
  std::memcpy(body.data() + at, &value, 4);
}

TEST(RosMessages, RoundTripAClip) {
  echoplan_ros::Clip clip;
  clip.sequence = 3;
  clip.action = "strike";
  clip.sample_rate = 16000;
  clip.channels = 2;
  clip.samples = {0.5f, -0.25f};
  std::vector<std::uint8_t> body = serialize(clip);
  echoplan_ros::Clip read;
  deserialize(body, read);
  EXPECT_EQ(read.samples, clip.samples);
  EXPECT_EQ(read.action, "strike");
}

// A float32[] count whose byte count wraps around 32 bits (0x40000001 x 4 = 4) used to pass the
// stream's bounds check, and memcpy then read 4 GiB past the body.
TEST(RosMessages, ArrayLengthWhoseByteCountWrapsIsAnOverrun) {
  echoplan_ros::Observe::Request request;
  request.action = "a";
  request.samples = {1.0f};
  std::vector<std::uint8_t> body = serialize(request);
  // action (4 + 1 bytes), clip_path (4), sample_rate (4), channels (4), then the samples' count.
  set_u32(body, 17, 0x40000001u);
  echoplan_ros::Observe::Request read;
  EXPECT_THROW(deserialize(body, read), ros::serialization::StreamOverrunException);
  EXPECT_TRUE(read.samples.empty());
}

// A string[] count the body cannot hold used to be allocated first (2^31 strings, 64 GiB).
TEST(RosMessages, StringArrayLongerThanTheBodyIsAnOverrunBeforeAllocating) {
  echoplan_ros::Observe::Response response;
  response.label = "mug";
  response.classes = {"mug"};
  std::vector<std::uint8_t> body = serialize(response);
  // label (4 + 3), unknown (1), probability (8), grade (4), then the classes' count.
  set_u32(body, 20, 0x7fffffffu);
  echoplan_ros::Observe::Response read;
  EXPECT_THROW(deserialize(body, read), ros::serialization::StreamOverrunException);
  EXPECT_TRUE(read.classes.empty());
}

}  // namespace
}  // namespace echoplan::robot
