#include "common/rng.h"

namespace echoplan {
namespace {
constexpr std::uint64_t kGolden = 0x9e3779b97f4a7c15ULL;  // SplitMix64's increment

std::uint64_t finalise(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}
}  // namespace

std::uint64_t splitmix64(std::uint64_t x) { return finalise(x + kGolden); }

std::uint64_t splitmix64_next(std::uint64_t& state) { return finalise(state += kGolden); }

std::uint64_t derive_seed(std::uint64_t seed, std::initializer_list<std::uint64_t> stream) {
  std::uint64_t h = splitmix64(seed);
  for (std::uint64_t s : stream) h = splitmix64(h ^ splitmix64(s + 0x632be59bd9b4e019ULL));
  return h;
}

}  // namespace echoplan
