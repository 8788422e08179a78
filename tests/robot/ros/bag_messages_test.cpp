// The bag import's message decoders against bytes laid out by hand from the ROS 1 wire format
// (little-endian numbers, a uint32 length before every string and array, the Header first).
#include "robot/ros/bag_messages.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "common/error.h"
#include "wire_bytes.h"

namespace echoplan::robot {
namespace {

using ::testing::HasSubstr;

TEST(BagMessages, DecodeAJointStateFieldByField) {
  Bytes m;
  m.header().u32(2).str("j1").str("j2");  // name
  m.u32(1).f64(0.25);                     // position: one value
  m.u32(0);                               // velocity: none
  m.u32(2).f64(1.5).f64(-2.0);            // effort
  const JointStateMessage js = decode_joint_state(m.b);
  EXPECT_EQ(js.name, (std::vector<std::string>{"j1", "j2"}));
  EXPECT_EQ(js.position, (std::vector<double>{0.25}));
  EXPECT_TRUE(js.velocity.empty());
  EXPECT_EQ(js.effort, (std::vector<double>{1.5, -2.0}));
}

TEST(BagMessages, DecodeAWrenchAndAString) {
  Bytes w;
  w.header().f64(1).f64(2).f64(3).f64(-4).f64(-5).f64(-6);
  const WrenchMessage wrench = decode_wrench_stamped(w.b);
  EXPECT_EQ(wrench.force[2], 3.0);
  EXPECT_EQ(wrench.torque[0], -4.0);
  Bytes s;
  s.str("start mug lift s1");
  EXPECT_EQ(decode_string(s.b), "start mug lift s1");
}

TEST(BagMessages, BadBytesAreInputErrorsSayingWhy) {
  Bytes short_wrench;
  short_wrench.header().f64(1).f64(2);
  EXPECT_THAT([&] { decode_wrench_stamped(short_wrench.b); },
              ::testing::ThrowsMessage<InputError>(HasSubstr("ends inside a field")));
  Bytes huge;  // four billion names in a few bytes: refused before anything is allocated
  huge.header().u32(0xFFFFFFFFu).str("j1");
  EXPECT_THAT([&] { decode_joint_state(huge.b); },
              ::testing::ThrowsMessage<InputError>(HasSubstr("an array of 4294967295 elements")));
  Bytes extra;
  extra.str("end").u32(1);
  EXPECT_THAT([&] { decode_string(extra.b); },
              ::testing::ThrowsMessage<InputError>(HasSubstr("4 bytes after its last field")));
}

}  // namespace
}  // namespace echoplan::robot
