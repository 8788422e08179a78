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

// retry_safe is the reply's last field: a driver built against the definition before it (one byte
// shorter) fails the md5sum check rather than being read as never safe to repeat.
TEST(RosMessages, AnExecuteActionReplyCarriesRetrySafeAfterTheDuration) {
  echoplan_ros::ExecuteAction::Response reply;
  reply.status = echoplan_ros::ExecuteAction::Response::FAILED;
  reply.reason = "slip";
  reply.duration_s = 0.5;
  reply.retry_safe = true;
  std::vector<std::uint8_t> body = serialize(reply);
  // status (1), reason (4 + 4), duration_s (8), retry_safe (1).
  ASSERT_EQ(body.size(), 18u);
  EXPECT_EQ(body[17], 1);
  echoplan_ros::ExecuteAction::Response read;
  deserialize(body, read);
  EXPECT_TRUE(read.retry_safe);
  EXPECT_EQ(read.duration_s, 0.5);
  // The md5sum of the definition without retry_safe.
  EXPECT_STRNE(ros::service_traits::md5sum<echoplan_ros::ExecuteAction>(),
               "7a9ee279c31d57056068c8a4b1577a80");
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
  // label (4 + 3), unknown (1), probability (8), grade (4), level_grade (4), then the classes'
  // count.
  set_u32(body, 24, 0x7fffffffu);
  echoplan_ros::Observe::Response read;
  EXPECT_THROW(deserialize(body, read), ros::serialization::StreamOverrunException);
  EXPECT_TRUE(read.classes.empty());
}

}  // namespace
}  // namespace echoplan::robot
