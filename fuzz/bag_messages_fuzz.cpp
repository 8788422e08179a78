// libFuzzer target: arbitrary bytes as the serialized body of each message a bag import decodes
// (robot/ros/bag_messages.h: JointState, WrenchStamped, String). Bad bytes must end in
// echoplan::InputError; anything else (a crash, a sanitizer report, another exception, a huge
// allocation, a hang) is a bug.
#include <cstddef>
#include <cstdint>
#include <span>

#include "common/error.h"
#include "robot/ros/bag_messages.h"

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
    echoplan::robot::decode_string(bytes);
  } catch (const echoplan::InputError&) {
  }
  return 0;
}
