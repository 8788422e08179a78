// libFuzzer target: arbitrary bytes as the serialized body of each message a bag import or the live
// observation node decodes (robot/ros/bag_messages.h: JointState, WrenchStamped, String), through
// the series topic readers both use (robot/ros/series_topic.h: two messages of a topic, so the
// second is read against the channels the first fixed) and as a performance marker's text. Bad
// bytes must end in echoplan::InputError; anything else (a crash, a sanitizer report, another
// exception, a huge allocation, a hang) is a bug.
#include <cstddef>
#include <cstdint>
#include <span>

#include "common/error.h"
#include "robot/ros/bag_messages.h"
#include "robot/ros/series_topic.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::span<const std::uint8_t> bytes(data, size);
  try {
    const auto js = echoplan::robot::decode_joint_state(bytes);
    if (js.name.size() + js.position.size() + js.effort.size() > size) __builtin_trap();
  } catch (const echoplan::InputError&) {
  }
  try {
    echoplan::robot::decode_wrench_stamped(bytes);
  } catch (const echoplan::InputError&) {
  }
  try {
    echoplan::robot::parse_performance_marker(echoplan::robot::decode_string(bytes));
  } catch (const echoplan::InputError&) {
  }
  // Each half of the input as one message of a topic.
  const auto first = bytes.first(size / 2), second = bytes.subspan(size / 2);
  for (const char* spec : {"effort=/joint_states:velocity", "force=/wrench:wrench"}) {
    echoplan::robot::SeriesTopicReader reader(echoplan::robot::parse_series_topic(spec));
    const bool joints = spec[0] == 'e';
    const char* type =
        joints ? echoplan::robot::kJointStateType : echoplan::robot::kWrenchStampedType;
    const char* md5 = joints ? echoplan::robot::kJointStateMd5 : echoplan::robot::kWrenchStampedMd5;
    for (const auto part : {first, second}) {
      try {
        const auto values = reader.read(type, md5, part);
        if (values.size() != reader.channels().size()) __builtin_trap();
      } catch (const echoplan::InputError&) {
      }
    }
  }
  return 0;
}
