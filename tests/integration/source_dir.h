#pragma once
/// The repository root, for integration tests that read worlds/ and experiments/: ctest sets
/// COGMAP_SOURCE_DIR; a test binary run by hand falls back to this header's place in the tree.

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace cogmap::integration {

inline std::filesystem::path source_dir() {
  const char* src = std::getenv("COGMAP_SOURCE_DIR");
  return src ? std::filesystem::path(src)
             : std::filesystem::path(__FILE__).parent_path().parent_path().parent_path();
}

/// The whole content of a file (empty when it cannot be read), for comparing run outputs.
inline std::string read_file(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace cogmap::integration
