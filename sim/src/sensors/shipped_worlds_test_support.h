#pragma once
// Test support shared by the sonar tests that compare two implementations on every shipped world.

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

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

}  // namespace cogmap::sim::test_support
