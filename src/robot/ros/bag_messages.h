// The three standard ROS 1 messages a bag import reads, decoded from their serialized bytes.
//
// Debian's generated headers for sensor_msgs, geometry_msgs and std_msgs do not compile as C++20
// (they name std::allocator<void>::rebind), and what the import needs of them is small and fixed,
// so their wire format is read here: little-endian numbers, a uint32 length before each string and
// array, a std_msgs/Header (uint32 seq, time stamp as two uint32, string frame_id) first in the
// stamped ones. Each decoder is checked against its type's MD5 sum, which names the layout.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace echoplan::robot {

inline constexpr const char* kJointStateType = "sensor_msgs/JointState";
inline constexpr const char* kWrenchStampedType = "geometry_msgs/WrenchStamped";
inline constexpr const char* kStringType = "std_msgs/String";
inline constexpr const char* kJointStateMd5 = "3066dcd76a6cfaef579bd0f34173e9fd";
inline constexpr const char* kWrenchStampedMd5 = "d78d3cb249ce23087ade7e7d0c40cfa7";
inline constexpr const char* kStringMd5 = "992ce8a1687cec8c8bd883ec73ca41d1";

struct JointStateMessage {
  std::vector<std::string> name;
  std::vector<double> position, velocity, effort;
};

struct WrenchMessage {
  double force[3]{};
  double torque[3]{};
};

// Each throws InputError("", 0, problem) when the bytes end early, an array claims more than the
// bytes hold, or bytes are left over.
JointStateMessage decode_joint_state(std::span<const std::uint8_t> bytes);
WrenchMessage decode_wrench_stamped(std::span<const std::uint8_t> bytes);
std::string decode_string(std::span<const std::uint8_t> bytes);

}  // namespace echoplan::robot
