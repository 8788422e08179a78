// A stable 64-bit number for a text (FNV-1a), the same on every platform and run: a stream id for
// derive_seed() that follows a name (an object, an action) rather than its position in a list, or a
// fingerprint of a file's bytes.
#pragma once

#include <cstdint>
#include <string_view>

namespace echoplan {

constexpr std::uint64_t stable_hash(std::string_view text) {
  std::uint64_t h = 14695981039346656037ULL;
  for (const char c : text) {
    h ^= static_cast<unsigned char>(c);
    h *= 1099511628211ULL;
  }
  return h;
}

}  // namespace echoplan
