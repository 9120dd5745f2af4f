#pragma once
// Test support shared by the sonar tests that compare two implementations on every shipped world.

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "sonar_raycast.h"

namespace cogmap::sim::test_support {

/// The repository's worlds/ (COGMAP_SOURCE_DIR overrides the source tree the build was made in).
inline std::filesystem::path worlds_dir() {
  const char* env = std::getenv("COGMAP_SOURCE_DIR");
  return std::filesystem::path(env ? env : COGMAP_SOURCE_DIR_FALLBACK) / "worlds";
}

inline std::filesystem::path world_path(const std::string& name) { return worlds_dir() / name; }

/// Every world the repository ships (worlds/*.yaml), sorted so failures are reproducible.
inline std::vector<std::filesystem::path> shipped_worlds() {
  std::vector<std::filesystem::path> out;
  for (const auto& e : std::filesystem::directory_iterator(worlds_dir())) {
    if (e.path().extension() == ".yaml") out.push_back(e.path());
  }
  std::sort(out.begin(), out.end());
  return out;
}

/// Equal to the last bit (also for -0.0 against 0.0, which == would call equal).
inline bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

/// Two ray hits the same to the last bit: surface, distance and point.
inline ::testing::AssertionResult same_hit(const sonar_detail::RayHit& a,
                                           const sonar_detail::RayHit& b) {
  if (a.surface == b.surface && same_bits(a.t_m, b.t_m) && same_bits(a.point.x(), b.point.x()) &&
      same_bits(a.point.y(), b.point.y())) {
    return ::testing::AssertionSuccess();
  }
  return ::testing::AssertionFailure() << "surface " << a.surface << " against " << b.surface
                                       << ", t " << a.t_m << " against " << b.t_m;
}

}  // namespace cogmap::sim::test_support
