// The one random-number engine of echoplan, and how independent streams are derived from one seed.
//
// Every random choice in the project flows from a single user-set seed: functions take an `Rng&`
// argument (never a global), and a component that needs its own stream (a trial, a recording, a
// planner) derives it with `derive_seed(seed, stream...)` so that adding a stream elsewhere does
// not shift the numbers this one sees.
#pragma once

#include <cstdint>
#include <initializer_list>
#include <random>

namespace echoplan {

using Rng = std::mt19937_64;

// Mixes a base seed with stream identifiers (splitmix64 finaliser); distinct inputs give
// statistically independent seeds.
std::uint64_t derive_seed(std::uint64_t seed, std::initializer_list<std::uint64_t> stream);

// SplitMix64 (Steele, Lea and Flood 2014): `splitmix64(x)` mixes one number into a well-spread
// one; `splitmix64_next(state)` advances a SplitMix64 generator and returns its next output.
std::uint64_t splitmix64(std::uint64_t x);
std::uint64_t splitmix64_next(std::uint64_t& state);

// A uniform double in [0, 1) from `rng`, identical on every platform
// (std::uniform_real_distribution is not specified bit for bit across standard libraries).
inline double uniform01(Rng& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

}  // namespace echoplan
