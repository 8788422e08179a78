// Tests' helper: ROS 1 messages laid out by hand in the wire format (little-endian numbers, a
// uint32 length before every string and array, the Header first in stamped messages), so decoders
// are checked against bytes that do not come from the code under test.
#pragma once

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace echoplan::robot {

// Appends the wire form of each value.
struct Bytes {
  std::vector<std::uint8_t> b;
  Bytes& u32(std::uint32_t v) { return raw(&v, 4); }
  Bytes& f64(double v) { return raw(&v, 8); }
  Bytes& str(const std::string& s) {
    u32(static_cast<std::uint32_t>(s.size()));
    return raw(s.data(), s.size());
  }
  Bytes& header() { return u32(7).u32(1700000000).u32(5).str("base_link"); }
  Bytes& raw(const void* p, std::size_t n) {
    const auto* c = static_cast<const std::uint8_t*>(p);
    b.insert(b.end(), c, c + n);
    return *this;
  }
};

}  // namespace echoplan::robot
