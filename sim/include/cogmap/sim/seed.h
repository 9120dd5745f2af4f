#pragma once
/// Derived random seeds: one run seed feeds several independent streams (sonar, odometry), so
/// changing one model's draws never shifts another's.

#include <cstdint>

namespace cogmap::sim {

/// SplitMix64 finaliser (Steele, Lea, Flood 2014): a bijective 64-bit mix.
constexpr std::uint64_t splitmix64(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

/// The seed of stream `stream` (1 sonar, 2 odometry, ...) of a run seeded with `seed`.
constexpr std::uint64_t derive_seed(std::uint64_t seed, std::uint64_t stream) {
  return splitmix64(splitmix64(seed) ^ splitmix64(stream * 0x2545f4914f6cdd1dULL));
}

}  // namespace cogmap::sim
