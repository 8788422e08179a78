#include "robot/ros/bag_messages.h"

#include <bit>
#include <cstring>

#include "common/error.h"

namespace echoplan::robot {

namespace {

static_assert(std::endian::native == std::endian::little, "ROS serializes little-endian");

// Reads the wire format front to back, refusing to read past the end.
class Reader {
 public:
  explicit Reader(std::span<const std::uint8_t> bytes) : bytes_(bytes) {}

  template <typename T>
  T number() {
    T value;
    std::memcpy(&value, take(sizeof(T)), sizeof(T));
    return value;
  }
  std::string text() {
    const std::uint32_t n = number<std::uint32_t>();
    const auto* p = reinterpret_cast<const char*>(take(n));
    return std::string(p, n);
  }
  std::vector<std::string> texts() {
    const std::uint32_t n = count(4);
    std::vector<std::string> out;
    for (std::uint32_t i = 0; i < n; ++i) out.push_back(text());
    return out;
  }
  std::vector<double> doubles() {
    const std::uint32_t n = count(sizeof(double));
    std::vector<double> out(n);
    if (n > 0) std::memcpy(out.data(), take(n * sizeof(double)), n * sizeof(double));
    return out;
  }
  void header() {
    number<std::uint32_t>();  // seq
    number<std::uint32_t>();  // stamp: seconds
    number<std::uint32_t>();  // nanoseconds
    text();                   // frame_id
  }
  void finish() const {
    if (at_ != bytes_.size())
      throw InputError(
          "", 0,
          "the message has " + std::to_string(bytes_.size() - at_) + " bytes after its last field");
  }

 private:
  // An array's element count, refused when the bytes left cannot hold that many elements of at
  // least `least` bytes (so a bad count allocates nothing).
  std::uint32_t count(std::size_t least) {
    const std::uint32_t n = number<std::uint32_t>();
    if (n > (bytes_.size() - at_) / least)
      throw InputError("", 0,
                       "an array of " + std::to_string(n) + " elements in " +
                           std::to_string(bytes_.size() - at_) + " bytes");
    return n;
  }
  const std::uint8_t* take(std::size_t n) {
    if (n > bytes_.size() - at_)
      throw InputError(
          "", 0, "the message ends inside a field (" + std::to_string(bytes_.size()) + " bytes)");
    const std::uint8_t* p = bytes_.data() + at_;
    at_ += n;
    return p;
  }

  std::span<const std::uint8_t> bytes_;
  std::size_t at_ = 0;
};

}  // namespace

JointStateMessage decode_joint_state(std::span<const std::uint8_t> bytes) {
  Reader r(bytes);
  r.header();
  JointStateMessage m;
  m.name = r.texts();
  m.position = r.doubles();
  m.velocity = r.doubles();
  m.effort = r.doubles();
  r.finish();
  return m;
}

WrenchMessage decode_wrench_stamped(std::span<const std::uint8_t> bytes) {
  Reader r(bytes);
  r.header();
  WrenchMessage m;
  for (double& f : m.force) f = r.number<double>();
  for (double& t : m.torque) t = r.number<double>();
  r.finish();
  return m;
}

std::string decode_string(std::span<const std::uint8_t> bytes) {
  Reader r(bytes);
  std::string s = r.text();
  r.finish();
  return s;
}

}  // namespace echoplan::robot
